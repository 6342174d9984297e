// Prisms as parts of CSG and transformed: a cubic prism with a cylinder
// taken away, the intersection of a Bezier prism and a sphere, a
// quadratic prism taken from a box, a conic prism clipped by a plane, a
// sphere clipped by a prism, and a linear one rotated and scaled
// unevenly, POV-Ray's logo (a prism in a difference) among them.
// (tests/prisms.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.4, 0> angle 52 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
difference {
  prism { cubic_spline 0, 0.7, 8,
    <0, -1>, <1, 0>, <0.2, 0.9>, <-0.8, 0.5>, <-0.7, -0.6>, <0, -1>, <1, 0>, <0.2, 0.9> }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.35 }
  translate <-2.3, 0, 1.2> pigment { rgb <0.2, 0.7, 0.3> } }
intersection {
  prism { bezier_spline -1, 1, 8,
    <0, -1>, <0.5, -0.5>, <1.2, 0.6>, <0, 0.4>, <0, 0.4>, <-1.2, 0.6>, <-0.5, -0.5>, <0, -1> }
  sphere { <0, 0, 0>, 0.9 }
  translate <0, 0.8, 1.4> pigment { rgb <0.9, 0.2, 0.4> } }
difference {
  box { <-0.9, 0, -0.9>, <0.9, 0.5, 0.9> }
  prism { quadratic_spline -1, 1, 11,
    <0.6, -0.6>, <1, 0>, <0.3, 0.3>, <0, 1>, <-0.3, 0.3>, <-1, 0>, <-0.3, -0.3>, <0, -1>, <0.3, -0.3>, <1, 0>, <0.3, 0.3>
    scale 0.7 }
  translate <2.3, 0, 1.2> pigment { rgb <0.9, 0.6, 0.2> } }
prism { conic_sweep cubic_spline 0.3, 1.2, 8,
  <0, -1>, <1, 0>, <0.2, 0.9>, <-0.8, 0.5>, <-0.7, -0.6>, <0, -1>, <1, 0>, <0.2, 0.9>
  clipped_by { plane { z, 0.2 } } translate <-1.5, 0, -1.3> pigment { rgb <0.3, 0.4, 0.9> } }
prism { linear_spline 0, 0.5, 5, <-0.5, -0.3>, <0.5, -0.3>, <0.5, 0.3>, <-0.5, 0.3>, <-0.5, -0.3>
  scale <1, 2, 0.5> rotate <20, 30, 40> translate <1.5, 0.6, -1.3> pigment { rgb <0.7, 0.5, 0.9> } }
sphere { 0, 0.8 clipped_by { prism { quadratic_spline -1, 0.3, 11,
    <0.6, -0.6>, <1, 0>, <0.3, 0.3>, <0, 1>, <-0.3, 0.3>, <-1, 0>, <-0.3, -0.3>, <0, -1>, <0.3, -0.3>, <1, 0>, <0.3, 0.3>
    rotate 20 * y } }
  translate <3.3, 0.6, 3.4> pigment { rgb <0.9, 0.9, 0.9> } }
#include "logo.inc"
object { Povray_Logo scale 0.6 rotate <0, 0, 0> translate <0, 0.6, -1.5> pigment { rgb <0.8, 0.8, 0.2> } }
