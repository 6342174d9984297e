// A smooth height field of a 16-bit grey picture, lit low from the side so that its
// hills shade and shadow each other (tests/planar-shapes.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 1.6, -1.1> look_at <0.5, 0.1, 0.5> angle 50 }
light_source { <-3, 1.5, 1>, rgb 1 }
light_source { <2, 6, -3>, rgb 0.3 }
height_field {
  png "hf-png16.png" smooth
  pigment { rgb <0.8, 0.7, 0.5> }
}
plane { y, 0 pigment { rgb <0.3, 0.4, 0.6> } }
