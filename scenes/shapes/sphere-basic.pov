// Spheres as POV-Ray renders them: sizes and colours, one resting on the
// floor (tangent to it), two touching each other, a filtering sphere that
// colours its shadow, a sphere shadowing a box and a triangle shadowing a
// sphere; two lights. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6.5> look_at <0, 0.7, 0> angle 50 }
light_source { <4, 7, -3> color rgb 1 }
light_source { <-6, 3, -1> color rgb <0.35, 0.35, 0.45> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.35 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.7 phong_size 30 } }
sphere { <-2.1, 0.45, 0.6>, 0.45 pigment { rgb <0.2, 0.7, 0.25> } }
sphere { <-2.1, 1.2, 0.6>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } }
sphere { <1.7, 0.7, -1.1>, 0.6 pigment { rgbf <0.3, 0.55, 1, 0.85> } }
box { <1.1, 0, 1.2>, <2.6, 1.2, 2.2> pigment { rgb 0.75 } }
sphere { <1.5, 2.1, 1.3>, 0.35 pigment { rgb <0.6, 0.3, 0.8> } }
triangle { <-0.9, 2.7, -0.2>, <0.6, 2.7, -0.4>, <-0.1, 2.7, 1.1> pigment { rgb <1, 0.9, 0.4> } }
sphere { <0.9, 0.15, -2.2>, 0.15 pigment { rgb 1 } }
