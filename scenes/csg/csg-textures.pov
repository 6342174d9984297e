// Textures of CSG parts (POV-Ray's rules): a part with its own texture
// keeps it, parts without one take the CSG object's; a taken-away part's
// texture shows on the walls it cuts; a patterned texture on the CSG
// object. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
difference {
    sphere { <-1.3, 1, 0>, 1 }
    sphere { <-1.3, 1.3, -0.9>, 0.7 pigment { rgb <0.2, 0.9, 0.3> } }
    cylinder { <-3, 0.8, 0>, <0, 0.8, 0>, 0.3 }
    pigment { rgb <0.9, 0.3, 0.2> }
}
intersection {
    sphere { <1.2, 1, 0>, 1 pigment { rgb <0.95, 0.9, 0.2> } finish { phong 0.8 } }
    cylinder { <1.2, 0, 0>, <1.2, 2, 0>, 0.8 }
    pigment { checker rgb <0.2, 0.3, 0.9>, rgb 0.95 scale 0.25 }
}
