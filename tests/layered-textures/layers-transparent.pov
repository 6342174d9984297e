// Layered textures whose upper layers are partly see-through: a bozo of
// clear and coloured filter spots over a checker, and three layers (a
// transmitting gradient over a filtering one over marble), on spheres and
// a box over a plane; the upper layers let the lower ones show, each lit
// with its own colour (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> angle 45 }
light_source { <-6, 9, -5>, rgb 1 }
light_source { <5, 5, -6>, rgb 0.35 }
#declare Spots =
  texture { pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.95, 0.9, 0.7> scale 0.3 } }
  texture { pigment { bozo color_map { [0.4 rgbf <1, 1, 1, 1>] [0.6 rgbf <0.2, 0.3, 0.9, 0.4>] [1 rgb <0.1, 0.5, 0.1>] } scale 0.4 } }
sphere { <-1.6, 0.9, 0>, 0.9 texture { Spots } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6>
  texture { pigment { marble turbulence 0.6 color_map { [0 rgb <0.3, 0.2, 0.1>] [1 rgb <0.9, 0.8, 0.6>] } } }
  texture { pigment { gradient y color_map { [0 rgbf <1, 0.8, 0.2, 0.7>] [1 rgbf <0.2, 0.6, 1, 0.2>] } scale 0.5 } }
  texture { pigment { gradient x color_map { [0 rgbt <0.8, 0.1, 0.1, 0.8>] [1 rgbt <1, 1, 1, 0.3>] } scale 0.4 } }
  rotate y * 30 translate <0.4, 0, 0.8>
}
// a declared layered texture, moved whole, and a layer put on it in the object
sphere { <1.8, 0.7, -0.3>, 0.7
  texture { Spots scale 1.7 rotate <10, 20, 0> }
  texture { pigment { wood color_map { [0 rgbt <0.5, 0.3, 0.1, 0.9>] [1 rgbt <0.4, 0.2, 0.05, 0.3>] } scale 0.2 } }
}
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } }
