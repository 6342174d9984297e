// CSG objects without bounds: two half-spaces intersected (a wedge with
// no end), and a merge of an inverted sphere with a sphere (all space but
// a hollow), seen from outside the hollow, next to a triangle.
// (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.3, 0> angle 60 }
light_source { <2, 4, -3> color rgb 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { rgb 1 } }
intersection { plane { y, 0 } plane { x, -0.5 } pigment { rgb <0.9, 0.3, 0.2> } }
merge { sphere { 0, 1.5 inverse } sphere { x, 0.5 } pigment { rgb <0.3, 0.8, 0.4> } translate 4 * z }
