// A POV-Ray 3.6 scene (#version 3.6): the layers' own light reduced by
// POV-Ray 3.6's formula, as woods.inc's textures are written for it, with
// an object transformed between its two layers (tests/layered-textures.sh).
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <-5, 8, -6>, rgb 1 }
sphere { <0, 0, 0>, 0.9
  texture { pigment { wood turbulence 0.1 color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.5, 0.25, 0.1>] } scale 0.2 } }
  translate <-1, 0.9, 0>
  texture { pigment { wood color_map { [0 rgbf <0.7, 0.3, 0.1, 0.8>] [0.6 rgbf <0.6, 0.35, 0.1, 0.9>] [1 rgbf <1, 1, 1, 1>] } scale 0.1 } }
}
box { <-0.7, 0, -0.7>, <0.7, 1.2, 0.7>
  texture { pigment { agate color_map { [0 rgb <0.9, 0.85, 0.7>] [1 rgb <0.4, 0.3, 0.2>] } } finish { phong 0.4 } }
  texture { pigment { gradient y color_map { [0 rgbf <0.9, 0.4, 0.1, 0.6>] [1 rgbf <0.1, 0.1, 0.1, 0.5>] } scale 0.35 } }
  rotate y * 20 translate <1.2, 0, 0.3>
}
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } }
