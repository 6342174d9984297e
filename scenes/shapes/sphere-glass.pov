// A glass sphere (refraction, ior 1.5) and a reflective one over a
// checker: rays entering and leaving the sphere's interior, a hollow
// sphere with the camera looking through both its sides, shadows through
// filtering glass. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.2, 0.3, 0.5> } }
plane { z, 4 pigment { rgb <0.6, 0.7, 0.6> } }
sphere { <-1.2, 1, 0>, 1 pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.9 } interior { ior 1.5 } }
sphere { <1.3, 0.8, 0.6>, 0.8 pigment { rgb 0.2 } finish { reflection 0.6 } }
sphere { <0.6, 0.45, -1.6>, 0.45 hollow pigment { rgbt <1, 0.8, 0.8, 0.7> } interior { ior 1.2 } }
