// inverse: on a part (an intersection with an inverted sphere is a
// difference), on a whole CSG object (an inverted intersection is the
// merge of the inverted parts: space outside the lens, here cut down to a
// box-like block by another intersection), and twice (no change).
// (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
intersection {
    sphere { <-1.6, 1, 0>, 1 }
    sphere { <-1.1, 1.4, -0.6>, 0.7 inverse }
    pigment { rgb <0.9, 0.5, 0.2> }
}
intersection {
    sphere { <0.4, 0.9, 0.3>, 0.9 }
    intersection {
        sphere { <0.1, 0.9, -0.5>, 0.6 }
        sphere { <0.7, 0.9, -0.5>, 0.6 }
        inverse
    }
    pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.5 }
}
difference {
    sphere { <2, 0.6, -1>, 0.6 inverse inverse }
    cylinder { <1, 0.6, -1>, <3, 0.6, -1>, 0.3 }
    pigment { rgb <0.5, 0.9, 0.4> }
}
