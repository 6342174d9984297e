// Cylindrical components (each a cylinder and two hemispheres) crossing and
// merging, one turned by its own transforms, one of negative strength; the
// blob scaled unevenly and rotated as a whole, with a see-through sphere
// component that becomes an ellipsoid (tests/blob.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -4>, rgb 1 }
light_source { <6, 5, -2>, rgb 0.35 }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.65> } }
blob {
  threshold 0.5
  cylinder { <-2.5, 0, 0>, <2.5, 0, 0>, 0.9, 1 }
  cylinder { <0, 0, -2>, <0, 0, 2>, 0.8, 1 rotate y * 30 }
  cylinder { <0, -1, 0>, <0, 1.5, 0>, 0.6, strength 1.5 scale <1, 1.2, 1> translate <1.5, 0, 0> }
  cylinder { <-1.5, 0.6, -1>, <-1.5, 0.6, 1>, 0.5, -1 }
  sphere { <0, 1, 0>, 0.9, 1 scale <1.5, 0.6, 1> rotate z * 20 }
  pigment { rgb <0.3, 0.7, 0.4> }
  finish { phong 0.5 }
  scale <1, 0.8, 1.2>
  rotate y * -15
  translate <0, 1, 0>
}
