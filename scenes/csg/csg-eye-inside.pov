// The eye inside a CSG object: the camera within a glass intersection
// (its interior's ior at the start of every camera ray) looking out
// through its far wall, and inside the bore of a difference (outside it).
// (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.2, -0.5> look_at <0, 0.8, 3> angle 60 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
plane { z, 6 pigment { rgb <0.6, 0.7, 0.6> } }
intersection {
    sphere { <0, 1, -1>, 2.2 }
    sphere { <0, 1, 0.5>, 2.2 }
    pigment { rgbf <0.95, 1, 0.95, 0.9> } interior { ior 1.3 }
}
difference {
    sphere { <1.2, 0.7, 2.5>, 0.7 }
    cylinder { <1.2, 0.7, 1>, <1.2, 0.7, 4>, 0.3 }
    pigment { rgb <0.9, 0.5, 0.2> }
}
