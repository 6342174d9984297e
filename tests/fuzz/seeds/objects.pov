// Objects, meshes, textures and the rest the scene language holds.
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1 max_trace_level 8 adc_bailout 0.01 ambient_light 0.2 }
background { rgb <0.1, 0.2, 0.3> }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 0.5>] } } }
fog { distance 30 rgbf <1, 1, 1, 0.2> turbulence 0.3 }
#declare T = texture { pigment { bozo turbulence 0.5 octaves 4 color_map { [0 Red] [0.5 Green] [1 Blue] } }
  finish { diffuse 0.7 phong 0.5 phong_size 20 specular 0.2 roughness 0.05 reflection { 0.1, 0.5 fresnel } } }
union {
  polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> texture { T } }
  smooth_triangle { <0, 0, 1>, <0, 1, 0>, <1, 0, 1>, <0, 1, 0>, <0, 1, 1>, <0, 1, 0> }
  mesh { triangle { 0, x, y } triangle { x, y, z texture { pigment { rgb 1 } } } }
  mesh2 {
    vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
    normal_vectors { 1, <0, 0, -1> }
    texture_list { 2, texture { pigment { Yellow } }, texture { pigment { wood } } }
    face_indices { 2, <0, 1, 2>, 0, <1, 3, 2>, 1 }
    normal_indices { 2, <0, 0, 0>, <0, 0, 0> }
  }
  box { -1, 1 pigment { marble scale 0.3 } interior { ior 1.3 fade_distance 2 fade_power 1 } hollow }
  light_source { <0, 3, 0>, rgb 0.5 fade_distance 3 fade_power 2 }
  translate <0, 1, 0> rotate <10, 20, 30> scale <1, 1.5, 1> matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0>
}
plane { <0, 1, 0>, -1 pigment { gradient x pigment_map { [0 Red] [1 checker Black, White scale 0.1] } } }
camera { orthographic location <0, 2, -6> look_at 0 right 4 * x up 3 * y }
light_source { <-3, 6, -2>, White parallel point_at 0 }
