// Sphere components made ellipsoids by a matrix and an uneven scale, a
// blob under `sturm` and one without its hierarchy, a threshold above the
// components' strength where two must meet (tests/blob.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.7, 0> angle 55 }
light_source { <-3, 8, -5>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.6 scale 0.8 } }
blob {
  threshold 0.9
  sphere { <0, 0, 0>, 1.2, 1 matrix <1, 0.3, 0, 0, 1, 0, 0.2, 0, 1, 0, 0, 0> }
  sphere { <0.8, 0.4, 0>, 1.0, 1 scale <1, 2, 1> }
  sphere { <-0.8, 0, 0.3>, 1.1, 0.8 }
  sturm
  pigment { rgb <0.85, 0.75, 0.3> }
  translate <-1.6, 1.1, 0>
}
blob {
  threshold 0.3
  sphere { <0, 0, 0>, 1, 1 }
  sphere { <0.9, 0, 0>, 0.8, 1 }
  sphere { <0.4, 0.8, 0>, 0.7, 1 }
  hierarchy off
  pigment { rgb <0.5, 0.4, 0.9> }
  finish { specular 0.4 }
  rotate z * 25
  translate <1.6, 0.9, 0.5>
}
