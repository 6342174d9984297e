// Layered textures casting shadows: a pane of two filtering layers (a red
// filter and a blue-green gradient) and a sphere with a transmitting layer
// over a filtering one let coloured light through, the product of the
// layers' filters; a box whose lower layer is opaque blocks the light
// whatever lies on it. One through glass of ior 1.5, one of ior 1
// (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <-2, 9, -4>, rgb 1 }
light_source { <4, 6, -3>, rgb 0.5 }
box { <-1.5, 0.8, -0.05>, <0.3, 2, 0.05>
  texture { pigment { rgbf <1, 0.3, 0.3, 0.9> } }
  texture { pigment { gradient x color_map { [0 rgbf <0.2, 1, 0.6, 0.8>] [1 rgbf <0.4, 0.5, 1, 1>] } scale 0.6 } }
  rotate x * -40
}
sphere { <1.3, 0.9, 0>, 0.7
  texture { pigment { bozo color_map { [0 rgbf <1, 0.9, 0.2, 0.9>] [1 rgbf <0.3, 0.9, 1, 0.7>] } scale 0.3 } }
  texture { pigment { rgbt <1, 1, 1, 0.7> } finish { phong 0.8 } }
  interior { ior 1.5 }
}
box { <-0.4, 0, -1.6>, <0.4, 0.6, -1>
  texture { pigment { rgb <0.6, 0.4, 0.2> } }
  texture { pigment { rgbt <0.2, 0.2, 0.9, 0.5> } }
}
sphere { <-1.8, 0.4, -1.2>, 0.4
  texture { pigment { rgbf <0.9, 0.9, 0.2, 0.8> } }
  texture { pigment { checker rgbt <1, 1, 1, 0.9>, rgbf <0.9, 0.2, 0.9, 0.9> scale 0.2 } }
}
plane { y, 0 pigment { rgb 0.8 } }
