// Transformed CSG: a lens and a bored sphere scaled unevenly, rotated and
// moved as whole objects, and a declared CSG object used twice with its
// own transforms. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
#declare Bored = difference {
    sphere { 0, 1 }
    cylinder { -2 * z, 2 * z, 0.4 }
    cylinder { -2 * x, 2 * x, 0.25 }
}
object { Bored scale 0.7 rotate <20, 35, 0> translate <-1.7, 0.8, 0> pigment { rgb <0.9, 0.5, 0.3> } }
object { Bored scale <0.5, 0.8, 0.6> rotate <-30, 10, 15> translate <0, 0.9, 0.6> pigment { rgb <0.4, 0.8, 0.4> } }
intersection {
    sphere { -0.5 * x, 1 }
    sphere { 0.5 * x, 1 }
    scale <0.8, 1.2, 0.8> rotate 60 * z translate <1.8, 1, -0.4>
    pigment { rgb <0.4, 0.5, 0.95> } finish { phong 0.6 }
}
