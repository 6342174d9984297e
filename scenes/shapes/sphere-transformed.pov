// Transformed spheres: an ellipsoid (scale not uniform), a sphere rotated
// and uniformly scaled (POV-Ray keeps it a sphere), one placed by a matrix
// and by transform { } (POV-Ray's ellipsoid path even where the shape stays
// round), a union scaled unevenly around two spheres, a mirrored one and an
// inverse one. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <5, 8, -4> color rgb 1 }
light_source { <-4, 5, -6> color rgb 0.4 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
sphere { <0, 0, 0>, 1 scale <1.4, 0.5, 0.8> rotate <0, 30, 20> translate <-2, 1.2, 0> pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <1, 0, 0>, 0.5 rotate 90 * y scale 1.3 translate <0, 0.65, 1.5> pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
sphere { 0, 0.6 matrix <1, 0, 0, 0.4, 1, 0, 0, 0, 1, 1.8, 0.8, 0.3> pigment { rgb <0.3, 0.4, 0.9> } }
sphere { 0, 0.4 transform { rotate 30 * z translate <0.2, 0.4, -1.4> } pigment { rgb <0.9, 0.9, 0.3> } }
union {
  sphere { <-0.5, 0, 0>, 0.35 }
  sphere { <0.5, 0, 0>, 0.35 }
  scale <1, 2, 1> translate <-0.6, 0.75, -2.2>
  pigment { rgb <0.8, 0.4, 0.9> }
}
sphere { <2.5, 0.5, -0.8>, 0.5 scale <-1, 1, 1> pigment { rgb <0.3, 0.8, 0.8> } }
sphere { <2.6, 1.8, 1.2>, 0.5 inverse pigment { rgb <1, 0.6, 0.3> } }
