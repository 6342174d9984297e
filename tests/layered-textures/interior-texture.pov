// interior_texture: the texture a ray meets where it reaches the surface
// from inside, on a sphere and a box cut open by see-through bands, a
// mirrored box, a cylinder and a torus; shadows through a sphere whose
// outer and interior textures filter the light in two colours, and a layered
// interior texture (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 9, -5>, rgb 1 }
light_source { <4, 5, -6>, rgb 0.4 }
sphere { <-2.2, 1, 0>, 1
  texture { pigment { gradient y color_map { [0 rgb <0.9, 0.3, 0.2>] [0.45 rgb <0.9, 0.5, 0.2>] [0.55 rgbt <1, 1, 1, 1>] [1 rgbt <1, 1, 1, 1>] } scale 0.4 } }
  interior_texture { pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
}
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7>
  texture { pigment { gradient x color_map { [0 rgbf <0.6, 0.8, 1, 0.9>] [0.4 rgbf <0.6, 0.8, 1, 0.9>] [0.6 rgb <0.8, 0.7, 0.3>] [1 rgb <0.8, 0.7, 0.3>] } scale 0.55 } }
  interior_texture { pigment { rgb <0.9, 0.2, 0.7> } }
  interior_texture { pigment { bozo color_map { [0 rgbt <1, 1, 1, 1>] [1 rgbt <0.2, 0.2, 0.9, 0.2>] } scale 0.2 } }
  rotate y * 30 translate <0.1, 0, 0.6>
}
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  texture { pigment { gradient z color_map { [0 rgb <0.3, 0.3, 0.8>] [0.45 rgb <0.3, 0.3, 0.8>] [0.55 rgbt 1] [1 rgbt 1] } scale 0.35 } }
  interior_texture { pigment { rgb <1, 0.9, 0.2> } }
  scale <-1, 1, 1> rotate y * 20 translate <2.2, 0, 1.2>
}
sphere { <1.9, 0.6, -1.3>, 0.6
  texture { pigment { rgbf <1, 0.4, 0.4, 0.9> } finish { phong 0.6 } }
  interior_texture { pigment { rgbf <0.4, 0.5, 1, 0.9> } }
}
cylinder { <-0.6, 0.3, -2>, <0.6, 0.3, -2>, 0.3
  texture { pigment { gradient x color_map { [0 rgb <0.7, 0.7, 0.7>] [0.5 rgb <0.7, 0.7, 0.7>] [0.6 rgbt 1] [1 rgbt 1] } scale 0.3 } }
  interior_texture { pigment { rgb <0.9, 0.4, 0.1> } }
}
torus { 0.5, 0.15
  texture { pigment { gradient x color_map { [0 rgb <0.2, 0.6, 0.6>] [0.5 rgb <0.2, 0.6, 0.6>] [0.6 rgbt 1] [1 rgbt 1] } scale 0.25 } }
  interior_texture { pigment { rgb <0.8, 0.8, 0.2> } }
  rotate x * -30 translate <-1.9, 0.6, -1.8>
}
plane { y, 0 pigment { rgb 0.75 } }
