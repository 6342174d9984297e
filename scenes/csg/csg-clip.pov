// clipped_by: a sphere clipped by a cylinder (its surface kept only inside
// the cylinder: an open band), a torus clipped by an inverted sphere, a
// union clipped by a sphere, clipped_by { bounded_by }, transforms after
// clipped_by moving object and clip together, and a clipped part in a
// difference. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
light_source { <-5, 6, -3> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
sphere {
    <-2, 1, 0>, 0.9
    clipped_by { cylinder { <-2, 0, 0>, <-2, 2, 0>, 0.6 } }
    pigment { rgb <0.9, 0.4, 0.3> }
}
torus {
    0.7, 0.2
    clipped_by { sphere { <0.5, 0, 0>, 0.6 inverse } }
    rotate -30 * x translate <-0.3, 0.6, -0.8>
    pigment { rgb <0.3, 0.8, 0.4> }
}
union {
    sphere { <1.2, 0.8, 0>, 0.6 }
    sphere { <1.8, 0.8, 0.3>, 0.6 }
    clipped_by { sphere { <1.5, 1.4, 0>, 0.9 } }
    pigment { rgb <0.4, 0.5, 0.95> } finish { phong 0.5 }
}
sphere {
    <0, 0, 0>, 0.5
    bounded_by { cylinder { <0, -1, 0>, <0, 1, 0>, 0.3 } }
    clipped_by { bounded_by }
    scale 1.5 translate <0.4, 1.6, 1.2>
    pigment { rgb <0.95, 0.85, 0.3> }
}
difference {
    cylinder { <2.2, 0, -1.6>, <2.2, 0.8, -1.6>, 0.5 }
    sphere { <2.2, 0.8, -1.6>, 0.4 clipped_by { cylinder { <2.2, 0, -1.6>, <2.2, 2, -1.6>, 0.25 } } }
    pigment { rgb <0.8, 0.5, 0.9> }
}
