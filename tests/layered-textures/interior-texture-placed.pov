// interior_texture placed by the object's transforms: given after a
// transform and before others, with a finish given on the object after it;
// on a box turned inside out (inverse: POV-Ray turns its normals); on a
// union, whose children take it (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -5>, rgb 1 }
sphere { <0, 0, 0>, 1
  texture { pigment { gradient y color_map { [0 rgb <0.9, 0.3, 0.2>] [0.45 rgb <0.9, 0.5, 0.2>] [0.55 rgbt 1] [1 rgbt 1] } scale 0.4 } }
  translate x * 0.3
  interior_texture { pigment { gradient x color_map { [0 rgb <0.2, 0.8, 0.3>] [1 rgb <0.1, 0.1, 0.8>] } scale 0.3 } }
  scale 1.2 rotate z * 20
  finish { phong 0.4 }
  translate <-1.2, 1.1, 0>
}
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7>
  interior_texture { pigment { gradient y color_map { [0 rgb <0.9, 0.2, 0.7>] [1 rgb <0.9, 0.9, 0.2>] } scale 0.3 } }
  translate y * 0.1
  texture { pigment { gradient x color_map { [0 rgbf <0.6, 0.8, 1, 0.9>] [0.4 rgbf <0.6, 0.8, 1, 0.9>] [0.6 rgb <0.8, 0.7, 0.3>] [1 rgb <0.8, 0.7, 0.3>] } scale 0.55 } }
  rotate y * 30 translate <1.3, 0, 0.6>
  inverse
}
union {
  sphere { <0, 0.4, -1.8>, 0.4 }
  box { <-0.4, 0.02, -0.4>, <0.4, 0.8, 0.4> rotate y * 15 translate <-0.3, 0, -2.6> }
  texture { pigment { gradient y color_map { [0 rgb <0.3, 0.6, 0.9>] [0.5 rgb <0.3, 0.6, 0.9>] [0.6 rgbt 1] [1 rgbt 1] } scale 0.2 translate y * 0.05 } }
  interior_texture { pigment { rgb <1, 0.5, 0> } }
  translate <0.3, 0, 1.2>
}
plane { y, 0 pigment { rgb 0.75 } }
