// A point light that looks like a glowing sphere, the sphere placed where
// the light is and moved with it by the transforms after looks_like, casting
// no shadow; a second light shines through it (tests/looks-like.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> angle 50 }
light_source {
  <0, 2, 0>, rgb <1, 0.9, 0.7>
  looks_like { sphere { 0, 0.4 pigment { rgb <1, 0.9, 0.6> } finish { ambient 1 diffuse 0 } } scale <1, 1.5, 1> }
  translate <-1, 0.5, 0>
}
light_source { <4, 6, -3>, rgb 0.6 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.5 } }
box { <0.5, 0, -0.5>, <1.5, 1, 0.5> pigment { rgb <0.3, 0.5, 0.9> } }
sphere { <-2.5, 0.6, 1>, 0.6 pigment { rgb <0.9, 0.4, 0.3> } }
