// Discs as POV-Ray renders them: a plain one, one with a hole, tilted,
// scaled unevenly, a see-through one filtering its shadow, and a disc
// seen edge-on (grazing rays). (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <4, 8, -4> color rgb 1 }
light_source { <-5, 4, -3> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
disc { <-2, 1.2, 0>, <0, 0, -1>, 0.9 pigment { rgb <0.9, 0.3, 0.2> } }
disc { <0, 1.5, 0.5>, <0.3, 1, -0.4>, 1, 0.45 pigment { rgb <0.2, 0.7, 0.3> } }
disc { <0, 0, 0>, y, 0.6 scale <1.8, 1, 0.7> rotate <-60, 20, 0> translate <2, 1.2, 0> pigment { rgb <0.3, 0.4, 0.9> } }
disc { <0.6, 0.7, -1.8>, <0.2, 1, -0.3>, 0.5 pigment { rgbf <1, 0.8, 0.3, 0.8> } }
disc { <-0.8, 0.5, -2.3>, <1, 0, 0>, 0.5 pigment { rgb 1 } }
