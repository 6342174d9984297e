// Lathes as POV-Ray renders them: linear, quadratic, cubic and Bezier
// splines (a vase, a bowl, a goblet, a knob), one with sturm, one turned
// and scaled unevenly, one with a box taken away (its inside in CSG),
// casting shadows on the floor; uv_mapping on one. (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
lathe { linear_spline 6, <0, 0>, <0.6, 0>, <0.7, 0.4>, <0.3, 1>, <0.5, 1.6>, <0, 1.6>
  translate <-2.4, 0, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
lathe { quadratic_spline 6, <0, -0.2>, <0, 0>, <0.6, 0.1>, <0.8, 0.6>, <0.7, 0.9>, <0.5, 1.2>
  sturm translate <-0.9, 0, 1.3> pigment { rgb <0.2, 0.7, 0.3> } }
lathe { cubic_spline 8, <0.3, -0.1>, <0, 0>, <0.5, 0.05>, <0.1, 0.4>, <0.12, 0.9>, <0.6, 1.1>, <0.5, 1.5>, <0.4, 1.6>
  translate <0.6, 0, 1.2> pigment { rgb <0.3, 0.4, 0.9> } }
lathe { bezier_spline 8, <0, 0>, <0.8, 0>, <0.8, 0.6>, <0.4, 0.7>, <0.4, 0.7>, <0.2, 0.8>, <0.5, 1.2>, <0, 1.3>
  scale <1, 0.8, 0.6> rotate <-30, 0, 25> translate <2.2, 0.8, 0.8> pigment { rgb <0.9, 0.8, 0.3> } }
difference {
  lathe { cubic_spline 6, <0, 0>, <0, 0>, <0.7, 0.2>, <0.5, 0.9>, <0, 1.2>, <0, 1.5> }
  box { <0, 0.3, -1>, <1, 2, 0> }
  translate <-1.4, 0, -1.2> pigment { rgb <0.8, 0.5, 0.9> }
}
lathe { linear_spline 5, <0.2, 0>, <0.5, 0>, <0.5, 0.8>, <0.2, 0.8>, <0.2, 0>
  translate <1.2, 0, -1.4> uv_mapping pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.3, 0.9> scale <0.125, 0.25, 1> } }
