// Transparent CSG casting filtered shadows: a see-through lens and a
// see-through bored sphere (light through both walls of each, and straight
// through the bore), a part with an opaque texture of its own in a
// see-through object. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
intersection {
    sphere { <-0.5, 1, 0>, 1.1 }
    sphere { <0.5, 1, 0>, 1.1 }
    pigment { rgbf <1, 0.5, 0.5, 0.8> }
    translate <-1.4, 0, 0>
}
difference {
    sphere { <1.3, 1, 0.3>, 0.9 }
    cylinder { <1.3, -1, 0.3>, <1.3, 3, 0.3>, 0.35 pigment { rgb <0.2, 0.2, 0.9> } }
    pigment { rgbt <0.5, 1, 0.5, 0.6> }
}
