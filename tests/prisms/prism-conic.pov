// Conic sweeps of curved prisms: a quadratic one between heights 0.2 and
// 1, a cubic one through its apex (heights -0.5 and 1), a Bezier one
// upside down (heights -1 and -0.3), an open cubic one seen inside.
// (tests/prisms.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, -0.8 pigment { checker rgb 0.85, rgb 0.4 } }
prism { conic_sweep quadratic_spline 0.2, 1, 11,
  <0.6, -0.6>, <1, 0>, <0.3, 0.3>, <0, 1>, <-0.3, 0.3>, <-1, 0>, <-0.3, -0.3>, <0, -1>, <0.3, -0.3>, <1, 0>, <0.3, 0.3>
  translate <-2.2, 0, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
prism { cubic_spline conic_sweep -0.5, 1, 8,
  <0, -1>, <1, 0>, <0.2, 0.9>, <-0.8, 0.5>, <-0.7, -0.6>, <0, -1>, <1, 0>, <0.2, 0.9>
  scale <0.8, 1, 0.8> translate <0, 0, 1.4> pigment { rgb <0.2, 0.7, 0.3> } }
prism { conic_sweep bezier_spline -1, -0.3, 8,
  <0, -1>, <0.5, -0.5>, <1.2, 0.6>, <0, 0.4>, <0, 0.4>, <-1.2, 0.6>, <-0.5, -0.5>, <0, -1>
  translate <2.2, 0.6, 1> pigment { rgb <0.9, 0.2, 0.4> } }
prism { cubic_spline 0, 0.8, 8,
  <0, -1>, <1, 0>, <0.2, 0.9>, <-0.8, 0.5>, <-0.7, -0.6>, <0, -1>, <1, 0>, <0.2, 0.9>
  open translate <0, -0.6, -1.4> pigment { rgb <0.3, 0.4, 0.9> } }
