// Object flags on curved objects: no_shadow, no_image (casts its shadow,
// unseen), no_reflection (seen, not in the mirror) and double_illuminate.
// (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <3, 6, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
plane { z, 3 pigment { rgb 0.2 } finish { reflection 0.5 } }
sphere { <-1.5, 0.8, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } no_shadow }
sphere { <0, 0.8, 0>, 0.6 pigment { rgb <0.2, 0.8, 0.3> } no_image }
sphere { <1.5, 0.8, 0>, 0.6 pigment { rgb <0.3, 0.4, 0.9> } no_reflection }
torus { 0.5, 0.1 rotate 90*x translate <0, 0.6, -1.5> pigment { rgb 1 } double_illuminate }
