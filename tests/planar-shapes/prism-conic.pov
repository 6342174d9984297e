// Conic-sweep prisms through their apex: one from below it to above (two
// pyramids meeting at the apex), one starting at it (no cap there), turned
// over (tests/planar-shapes.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 8, -4>, rgb 1 }
prism { conic_sweep linear_spline -0.5, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  translate <-1.5, 1, 0> pigment { rgb <0.8, 0.5, 0.3> } }
prism { conic_sweep 0, 1, 4, <-1, -1>, <1, -1>, <0, 1>, <-1, -1>
  rotate x * 180 translate <1.5, 1.2, 0> pigment { rgb <0.3, 0.7, 0.5> } }
plane { y, -0.2 pigment { rgb 0.6 } }
