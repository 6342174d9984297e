// Layers with normals of their own: a bumpy base under a smooth,
// see-through coat, and a smooth base under a wrinkled coat; each layer is
// lit and reflects with its own normal (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.7, 0> angle 45 }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <5, 4, -5>, rgb 0.3 }
sphere { <-1.2, 0.9, 0>, 0.9
  texture { pigment { rgb <0.7, 0.5, 0.3> } normal { bumps 0.8 scale 0.15 } finish { phong 0.6 } }
  texture { pigment { spotted color_map { [0.3 rgbf <1, 1, 1, 1>] [0.8 rgbf <0.1, 0.4, 0.2, 0.3>] } scale 0.2 }
            finish { reflection 0.2 } }
}
sphere { <1.2, 0.9, 0>, 0.9
  texture { pigment { rgb <0.3, 0.4, 0.8> } finish { specular 0.7 reflection 0.15 } }
  texture { pigment { rgbt <0.9, 0.9, 0.9, 0.6> } normal { wrinkles 0.7 scale 0.3 } finish { phong 0.8 } }
}
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } }
