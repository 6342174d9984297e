// Boxes and planes as CSG parts (POV-Ray's box and plane: a box is a solid
// between its corners, a plane the half-space below it): a box minus a
// sphere, the rounded cube (a box and a sphere intersected), a sphere cut
// by a plane (a hemisphere) and by an inverted one, a turned and unevenly
// scaled box with a cylinder bored through, a sphere clipped by a plane.
// (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.7, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
light_source { <-5, 6, -3> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
difference {
    box { <-2.8, 0, -0.5>, <-1.8, 1, 0.5> }
    sphere { <-1.8, 1, -0.5>, 0.6 }
    pigment { rgb <0.9, 0.4, 0.3> }
}
intersection {
    box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> }
    sphere { <0, 0.6, 0>, 0.8 }
    pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.5 }
    rotate 25 * y translate <-0.3, 0, 1.2>
}
intersection {
    sphere { <1.6, 0.7, 0>, 0.7 }
    plane { <1, 1, -1>, 0 translate <1.6, 0.7, 0> }
    pigment { rgb <0.4, 0.5, 0.95> }
}
intersection {
    sphere { <0.5, 0.5, -1.5>, 0.5 }
    plane { y, 0.6 inverse }
    pigment { rgb <0.95, 0.85, 0.3> }
}
difference {
    box { -0.5, 0.5 scale <1, 0.6, 0.8> rotate <10, 30, 0> }
    cylinder { -x, x, 0.2 }
    rotate 15 * z translate <2.4, 0.6, -1.4>
    pigment { rgb <0.8, 0.5, 0.9> }
}
sphere {
    <-1.3, 0.5, -1.6>, 0.5
    clipped_by { plane { -z, 1.7 } }
    pigment { rgb <0.5, 0.9, 0.9> }
}
