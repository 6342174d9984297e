// poly, cubic and quartic as POV-Ray renders them (tests/poly-shapes.sh):
// a torus written as a quartic (the closed-form solver), the same with
// sturm, turned and scaled unevenly; an infinite quartic cylinder
// x^4 + z^4 = 0.04 bounded_by a sphere, which POV-Ray keeps and tests
// first (only lines through the sphere meet it, shadow rays too); a cubic
// monkey saddle y = x^3 - 3 x z^2 cut by a sphere (an intersection, sturm);
// a poly of order 6, x^6 + y^6 + z^6 = 1 (the Sturm solver always), with
// a box taken away; all casting shadows on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -9> look_at <0, 0.8, 0> angle 52 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
#declare Torus = quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.18,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.82, 0, 0, 0, 0,
    1, 0, -2.18, 0, 0.8281>
}
object { Torus translate <-2.6, 0.3, 1.2> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
object { Torus sturm scale <0.8, 1.4, 0.6> rotate <60, 20, 0> translate <-2.2, 1, -1.4> pigment { rgb <0.9, 0.8, 0.3> } }
quartic {
  <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 0, -0.04>
  bounded_by { sphere { <0, 1, 0>, 1 } }
  translate <-0.2, 0, 1.8> pigment { rgb <0.2, 0.7, 0.3> }
}
intersection {
  cubic {
    <1, 0, 0, 0, 0, 0, 0, -3, 0, 0,
    0, 0, 0, 0, 0, -1, 0, 0, 0, 0>
    sturm
  }
  sphere { 0, 1 }
  translate <1.9, 1.1, 1.2> pigment { rgb <0.3, 0.4, 0.9> }
}
difference {
  poly { 6,
    <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
    0, 0, 0, -1>
  }
  box { <0, 0, -2>, <2, 2, 0> }
  scale 0.8 rotate 25 * y translate <1.3, 0.8, -1.6> pigment { rgb <0.8, 0.5, 0.9> }
}
