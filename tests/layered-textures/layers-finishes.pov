// Layers with finishes of their own: a phong and reflecting base under a
// matte, half-transmitting coat; a specular, metallic base under a
// filtering one with conserve_energy reflection; an emitting bottom layer.
// Each layer is lit with its finish and reflects with its own weight
// (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 3, -7> look_at <0, 0.7, 0> angle 45 }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <6, 3, -4>, rgb <0.4, 0.4, 0.5> }
sphere { <-1.7, 0.9, 0>, 0.9
  texture { pigment { rgb <0.8, 0.1, 0.1> } finish { phong 0.9 phong_size 60 reflection 0.3 } }
  texture { pigment { granite color_map { [0.3 rgbt <0.9, 0.9, 0.8, 1>] [0.7 rgbt <0.9, 0.9, 0.8, 0.4>] } scale 0.6 }
            finish { diffuse 0.9 ambient 0.2 } }
}
sphere { <0.2, 0.9, 0.6>, 0.9
  texture { pigment { rgb <0.9, 0.7, 0.2> } finish { specular 0.8 roughness 0.02 metallic 0.7 brilliance 3 } }
  texture { pigment { spiral1 3 color_map { [0.5 rgbf <0.2, 0.9, 0.4, 0.8>] [0.5 rgbf <1, 1, 1, 0.95>] } }
            finish { reflection { 0.1, 0.5 fresnel } conserve_energy diffuse 0.3 } }
  interior { ior 1.3 }
}
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  texture { pigment { rgb <0.2, 0.3, 0.9> } finish { emission 0.4 diffuse 0.2 } }
  texture { pigment { gradient y color_map { [0.5 rgbt <1, 1, 0.2, 0.6>] [0.5 rgb <0.1, 0.1, 0.1>] } scale 0.45 translate y * 0.2 } finish { phong 0.5 } }
  rotate y * -25 translate <2, 0, -0.6>
}
plane { y, 0 pigment { checker rgb 0.75, rgb 0.45 } finish { reflection 0.1 } }
