// Grazing rays: the camera in the plane of a quartic torus seen edge on
// (rays along its tube's top and bottom silhouettes), a quadric cylinder
// whose side the column of rays at x = 1 just touches (a discriminant of
// 0: POV-Ray's quadric misses it), a quadric cone seen along its axis
// from its apex, and the light grazing the floor beside them.
// (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 0.25, -6> look_at <1, 0.25, 0> angle 40 }
light_source { <8, 1.2, -2> color rgb 1 }
light_source { <-3, 6, -6> color rgb 0.4 }
plane { y, -0.5 pigment { checker rgb 0.85, rgb 0.4 } }
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.125,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.875, 0, 0, 0, 0,
    1, 0, -2.125, 0, 0.878906>
  translate <-0.3, 0.25, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 }
}
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
  plane { y, 0.9 } plane { -y, 0.5 }
  translate <0, 0, 3> pigment { rgb <0.2, 0.7, 0.3> }
}
intersection {
  quadric { <1, 1, -1>, <0, 0, 0>, <0, 0, 0>, 0 }
  plane { z, 2 } plane { -z, 0 }
  scale 0.2 translate <2.3, 0.25, -2> pigment { rgb <0.3, 0.4, 0.9> }
}
