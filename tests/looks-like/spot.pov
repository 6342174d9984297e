// A spotlight and a cylinder light, each with a looks_like object given its
// own modifiers inside the block; one of them without a texture takes the
// default; the lights rotated after (tests/looks-like.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.5, 0> angle 55 }
light_source {
  <2, 3, -1>, rgb 1.5
  spotlight point_at <1, 0, 1> radius 20 falloff 30
  looks_like { cone { 0, 0.1, <0, 0.4, 0>, 0.3 } rotate z * 30 pigment { rgb <0.9, 0.9, 0.2> } finish { ambient 0.8 } }
  rotate y * -20
}
light_source {
  <-2, 3, 0>, rgb 0.7
  cylinder point_at <-2, 0, 0> radius 1 falloff 1.5
  looks_like { torus { 0.3, 0.08 } }
  rotate z * 10
}
light_source { <3, 8, -6>, rgb 0.3 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } }
sphere { <1, 0.5, 1>, 0.5 pigment { rgb <0.4, 0.8, 0.4> } }
box { <-2.5, 0, -0.3>, <-1.5, 0.8, 0.3> pigment { rgb <0.8, 0.3, 0.5> } }
