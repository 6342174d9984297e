// Superellipsoids as POV-Ray renders them (its own root finder): rounded
// boxes and cylinders, a pinched star (e, n > 2), one turned and scaled
// unevenly, one with a sphere taken away (a CSG part: all its crossings),
// one inverted inside an intersection, all casting shadows on the floor.
// (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -4.8> look_at <0, 0.7, 0> angle 58 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
superellipsoid { <0.2, 0.2> scale 0.5 translate <-2.2, 0.5, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
superellipsoid { <1, 0.25> scale 0.5 rotate 90 * x translate <-0.9, 0.5, 1.3> pigment { rgb <0.2, 0.7, 0.3> } }
superellipsoid { <2.5, 2.5> scale 0.6 translate <0.4, 0.7, 1.4> pigment { rgb <0.3, 0.4, 0.9> } }
superellipsoid { <0.5, 1.5> scale <0.7, 0.4, 0.3> rotate <20, 40, 10> translate <1.8, 0.6, 0.9> pigment { rgb <0.9, 0.8, 0.3> } }
difference {
  superellipsoid { <0.3, 0.3> }
  sphere { <0.6, 0.6, -0.6>, 0.8 }
  scale 0.45 translate <-1.4, 0.45, -0.6> pigment { rgb <0.8, 0.5, 0.9> }
}
intersection {
  sphere { 0, 1 }
  superellipsoid { <0.6, 0.6> scale 0.6 inverse }
  scale 0.5 translate <1.1, 0.5, -0.8> pigment { rgb <0.2, 0.8, 0.9> }
}
