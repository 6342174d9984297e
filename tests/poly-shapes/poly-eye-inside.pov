// The eye inside: the camera within a see-through rounded cube
// x^4 + y^4 + z^4 = 16 (a quartic) and within a see-through ellipsoid
// (a quadric), both lit from outside, their insides seen from within and
// a solid quartic torus and a quadric cylinder outside them, casting
// shadows through both. (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -1.2> look_at <0, 0.6, 3> angle 70 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.85, rgb 0.4 } }
quartic {
  <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 0, -16>
  translate <0, 1, 0> pigment { rgbf <0.9, 1, 0.9, 0.85> } finish { phong 0.4 }
}
quadric { <0.25, 0.5, 0.2>, <0, 0, 0>, <0, 0, 0>, -1 translate <0, 1, -0.5> pigment { rgbf <1, 0.9, 0.9, 0.9> } }
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.18,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.82, 0, 0, 0, 0,
    1, 0, -2.18, 0, 0.8281>
  rotate 70 * x translate <1, 0.5, 4> pigment { rgb <0.9, 0.3, 0.2> }
}
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.09 translate <-1.4, 0, 4> pigment { rgb <0.2, 0.7, 0.3> } }
