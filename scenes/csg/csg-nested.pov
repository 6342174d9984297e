// Nested CSG: a difference whose first part is an intersection and whose
// taken-away part is a union (a union inside CSG is one solid, inside where
// any of its parts is), and a merge-free nest three levels deep; inner
// parts transformed on their own. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
light_source { <-5, 6, -3> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
difference {
    intersection {
        sphere { <-1, 1, 0>, 1.2 }
        cylinder { <-1, 0, 0>, <-1, 2, 0>, 1 }
    }
    union {
        cylinder { <-3, 1, 0>, <1, 1, 0>, 0.35 }
        sphere { <-1, 2, 0>, 0.5 }
        torus { 0.9, 0.15 translate <-1, 0.3, 0> }
    }
    pigment { rgb <0.9, 0.45, 0.25> } finish { phong 0.4 }
}
intersection {
    difference {
        intersection {
            sphere { <1.5, 0.8, 0>, 0.8 }
            sphere { <1.5, 0.8, 0>, 0.8 scale <1, 0.6, 1> translate <0, 0.35, 0> }
        }
        cone { <1.5, 0.2, 0>, 0.1, <1.5, 1.6, 0>, 0.45 }
    }
    cylinder { <1.5, 0, 0>, <1.5, 2, 0>, 0.7 rotate <0, 0, 5> }
    pigment { rgb <0.3, 0.7, 0.9> }
}
