// Cones as POV-Ray renders them: capped and open, a pointed one (radius
// 0 at one end), ends given wide end first and narrow end first, tilted,
// scaled unevenly, one nearly a cylinder, a see-through one filtering its
// shadow, and a cone resting on its tip. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <4, 8, -4> color rgb 1 }
light_source { <-5, 4, -3> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
cone { <-2.2, 0, 0>, 0.7, <-2.2, 1.6, 0>, 0 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
cone { <-0.6, 1.8, 0.8>, 0.2, <-0.6, 0.3, 0.8>, 0.6 open pigment { rgb <0.2, 0.7, 0.3> } }
cone { <1.2, 0.3, -0.2>, 0.5, <2.4, 1.3, 0.6>, 0.15 pigment { rgb <0.3, 0.4, 0.9> } }
cone { 0, 0.4, y, 0.2 scale <1.5, 1.2, 0.7> rotate -30 * y translate <0.3, 0, -1.1> pigment { rgb <0.9, 0.8, 0.3> } }
cone { <-1.4, 0, -1.6>, 0.3, <-1.4, 0.9, -1.6>, 0.3000000001 pigment { rgb 1 } }
cone { <1.7, 0.02, -2>, 0.35, <1.7, 0.8, -2>, 0.1 pigment { rgbf <0.6, 0.9, 1, 0.8> } }
cone { <0.4, 0, 1.8>, 0, <0.4, 1.2, 1.8>, 0.6 pigment { rgb <0.8, 0.5, 0.9> } }
