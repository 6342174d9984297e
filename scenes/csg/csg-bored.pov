// CSG difference: a sphere with a cylinder bored through it (the bore's
// inner wall seen through the hole, light through it onto the floor), a
// cone minus a sphere, a torus cut by a disc's half-space. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <2, 9, -5> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
difference {
    sphere { <-1.5, 1.1, 0>, 1.1 }
    cylinder { <-1.5, 1.1, -2>, <-1.5, 1.1, 2>, 0.45 }
    cylinder { <-1.5, -1, 0>, <-1.5, 3, 0>, 0.3 }
    pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.5 }
}
difference {
    cone { <1.2, 0, 0.5>, 1, <1.2, 1.8, 0.5>, 0.2 }
    sphere { <1.2, 1.0, -0.2>, 0.6 }
    pigment { rgb <0.3, 0.8, 0.4> }
}
difference {
    torus { 0.6, 0.2 translate <0.2, 0.3, -1.6> }
    disc { <0.2, 0.3, -1.6>, <1, 0, 0>, 2 }
    pigment { rgb <0.8, 0.8, 0.3> }
}
