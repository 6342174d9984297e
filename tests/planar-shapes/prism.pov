// Linear-spline prisms: a linear sweep with a hole (two outlines, the
// second left for the parser to close, no comma between them, as POV-Ray's
// prism3a.pov writes its outlines), an open one, and a conic sweep,
// transformed and casting shadows on each other (tests/planar-shapes.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 8, -4>, rgb 1 }
light_source { <6, 4, -5>, rgb 0.3 }
prism {
  linear_spline linear_sweep 0, 1.2, 10,
  <-1, -1>, <1.5, -1>, <1.5, 0.5>, <0, 1.5>, <-1, 0.5>, <-1, -1>
  <-0.5, -0.5>, <0.7, -0.5>, <0.7, 0.3>, <-0.5, 0.3>
  translate <-1.8, 0, 0.5>
  pigment { rgb <0.8, 0.5, 0.3> }
}
prism {
  0.2, 0.9, 5, <0, 0>, <1, 0>, <1.2, 1>, <0.2, 1.4>, <0, 0>
  open
  rotate <0, 30, 15> translate <1, 0, -1.2>
  pigment { rgb <0.4, 0.7, 0.5> }
}
prism {
  conic_sweep linear_spline 0.4, 1, 4, <-1, -1>, <1, -1>, <0.2, 1>, <-1, -1>
  rotate x * 180 translate <1.8, 1.2, 1.2>
  pigment { rgb <0.5, 0.6, 0.9> }
}
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } }
