// Quadrics as POV-Ray renders them: an ellipsoid, an infinite cylinder
// clipped by a box, a cone and a hyperboloid of one sheet bounded in
// CSG, a paraboloid cut by a plane, one turned and scaled unevenly (its
// coefficients carried by the transform), one inverted inside a CSG
// intersection, all casting shadows on the floor. (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
// an ellipsoid x^2/1 + y^2/0.49 + z^2/0.64 = 1
quadric { <1, 2.0408163, 1.5625>, <0, 0, 0>, <0, 0, 0>, -1
  translate <-2.6, 0.7, 0.5> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
// a cylinder along y of radius 0.45, clipped to a height of 2
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.2025
  clipped_by { box { <-1, 0, -1>, <1, 2, 1> } }
  translate <-0.9, 0, 1.5> pigment { rgb <0.2, 0.7, 0.3> } }
// a cone x^2 + z^2 = y^2 / 4 between y = 0 and 1.6 (by intersection)
intersection {
  quadric { <1, -0.25, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  box { <-2, 0.01, -2>, <2, 1.6, 2> }
  translate <0.8, 0, 1.2> pigment { rgb <0.3, 0.4, 0.9> }
}
// a hyperboloid of one sheet x^2 - y^2 + z^2 = 0.09, a merge with a disc cap
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.09 }
  plane { y, 1.2 } plane { -y, 0 }
  translate <2.6, 0, 1.4> pigment { rgb <0.9, 0.8, 0.3> }
}
// a paraboloid y = x^2 + z^2 (linear term), cut by a plane, turned and scaled unevenly
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }
  plane { y, 0.8 }
  scale <1, 1.3, 0.7> rotate <-25, 0, 30> translate <1.4, 0.6, -1.6> pigment { rgb <0.8, 0.5, 0.9> }
}
// a sphere with the ellipsoid taken away (an inverted quadric as a part), mixed terms
difference {
  sphere { 0, 0.6 }
  quadric { <1, 1, 1>, <0.8, 0, 0>, <0, 0, 0>, -0.12 translate <0.35, 0.3, -0.3> }
  translate <-1.5, 0.6, -1.7> pigment { rgb <0.2, 0.8, 0.9> }
}
