// Cylinders as POV-Ray renders them: capped and open, upright, lying,
// tilted, scaled unevenly, a thin rod grazing the floor, one see-through
// filtering its shadow (clear of the floor: a cap in the floor's plane is a tie), and one seen straight along its axis.
// (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <4, 8, -4> color rgb 1 }
light_source { <-5, 4, -3> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
cylinder { <-2.2, 0, 0>, <-2.2, 1.6, 0>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
cylinder { <-0.9, 0.3, 0.4>, <0.7, 0.3, 1.2>, 0.3 pigment { rgb <0.2, 0.7, 0.3> } }
cylinder { <1.4, 0.2, -0.5>, <2.2, 1.6, 0.3>, 0.35 open pigment { rgb <0.3, 0.4, 0.9> } }
cylinder { 0, y, 0.5 scale <1, 1.2, 0.5> rotate 30 * y translate <0.2, 0, -1.2> pigment { rgb <0.9, 0.8, 0.3> } }
cylinder { <-1.5, 0.05, -1.8>, <0.2, 0.05, -2.4>, 0.05 pigment { rgb 1 } }
cylinder { <1.6, 0.02, -2>, <1.6, 0.8, -2>, 0.3 pigment { rgbf <0.6, 0.9, 1, 0.8> } }
#declare Eye = <0, 3, -7>;
#declare P = <-0.9, 1.7, -2.5>;
cylinder { P, P + 0.6 * vnormalize(P - Eye), 0.2 pigment { rgb <1, 0.4, 1> } }
