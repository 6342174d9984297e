// A declared light with its looks_like used twice, each use moved on its
// own; an area light and a parallel light with theirs; a light inside a
// union moved with the union (tests/looks-like.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }
#declare Lamp = light_source {
  <0, 2.5, 0>, rgb 0.6
  looks_like { sphere { 0, 0.25 pigment { rgbf <1, 1, 0.8, 0.5> } finish { ambient 0.7 } } }
}
light_source { Lamp translate <-2, 0, 0> }
object { Lamp translate <2, 0, 1> }
light_source {
  <0, 3, -2>, rgb 0.5
  area_light x * 0.6, z * 0.6, 3, 3
  looks_like { box { -0.3, 0.3 scale <1, 0.1, 1> pigment { rgb 1 } finish { ambient 1 } } }
}
light_source {
  <4, 5, -4>, rgb 0.3 parallel point_at 0
  looks_like { sphere { 0, 0.3 pigment { rgb <0.2, 0.2, 1> } } }
}
union {
  sphere { <0, 0.7, 1.5>, 0.7 pigment { rgb <0.9, 0.5, 0.3> } }
  light_source { <0, 2, 1.5>, rgb 0.4 looks_like { sphere { 0, 0.15 pigment { rgb <1, 0, 0> } finish { ambient 1 } } } }
  translate <0.5, 0, 0>
}
plane { y, 0 pigment { checker rgb 0.75, rgb 0.55 } }
box { <-3, 0, 1.5>, <-1.5, 1.2, 2.5> pigment { rgb <0.3, 0.6, 0.8> } }
