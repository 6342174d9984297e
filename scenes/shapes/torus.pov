// Tori as POV-Ray renders them: lying on the floor (tangent to it), stood
// upright, linked, tilted and unevenly scaled, one with `sturm`, a thin
// one, a see-through one filtering its shadow, and uv_mapping on one (the
// checker about its two circles). (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <4, 8, -4> color rgb 1 }
light_source { <-5, 4, -3> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
torus { 0.8, 0.25 translate <-2, 0.25, 0.5> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
torus { 0.6, 0.2 rotate 90 * x translate <0, 0.8, 0.8> pigment { rgb <0.2, 0.7, 0.3> } }
torus { 0.6, 0.2 rotate 90 * z translate <0.6, 0.8, 0.8> pigment { rgb <0.3, 0.4, 0.9> } sturm }
torus { 0.5, 0.15 scale <1.4, 1, 0.8> rotate <30, 20, 0> translate <2.1, 0.9, -0.3> pigment { rgb <0.9, 0.8, 0.3> } }
torus { 0.7, 0.03 rotate -20 * x translate <-0.5, 0.6, -1.6> pigment { rgb 1 } }
torus { 0.4, 0.15 translate <1.3, 0.17, -1.9> pigment { rgbf <0.6, 0.9, 1, 0.8> } }
torus { 0.5, 0.22 rotate -60 * x translate <-2.2, 1.4, -0.9> uv_mapping pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.3, 0.9> scale <0.125, 0.25, 1> } finish { ambient 0.6 } }
