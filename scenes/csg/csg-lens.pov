// CSG intersection: a lens, the overlap of two spheres, and the overlap of
// a sphere and a cylinder; a point of a part counts where it is inside
// every other part. Shadows of both on the floor. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
intersection {
    sphere { <-0.6, 1, 0>, 1.2 }
    sphere { <0.6, 1, 0>, 1.2 }
    pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.7 }
    translate -1.3 * x
}
intersection {
    sphere { <1.6, 0.9, 0>, 0.9 }
    cylinder { <1.6, 0.9, -2>, <1.6, 0.9, 2>, 0.6 }
    pigment { rgb <0.3, 0.5, 0.9> }
}
