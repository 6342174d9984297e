// Surfaces of revolution as POV-Ray renders them: a closed vase (base
// and cap discs), an open cup seen into, one with sturm, one turned and
// scaled unevenly, one with a box taken away (its inside in CSG), casting
// shadows on the floor; uv_mapping on one. (tests/poly-shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 5, -2> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
#declare Vase = sor { 8, <0, -0.1>, <0.4, 0>, <0.6, 0.3>, <0.35, 0.8>, <0.25, 1.1>, <0.4, 1.5>, <0.45, 1.6>, <0.3, 1.7> }
object { Vase translate <-2.4, 0, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sor { 6, <0.2, -0.1>, <0.3, 0>, <0.6, 0.5>, <0.7, 0.9>, <0.75, 1.0>, <0.8, 1.1> open
  sturm translate <-0.8, 0, 1.3> pigment { rgb <0.2, 0.7, 0.3> } }
object { Vase scale <1, 0.8, 0.6> rotate <-30, 0, 25> translate <2.2, 0.8, 0.8> pigment { rgb <0.9, 0.8, 0.3> } }
difference {
  object { Vase }
  box { <0, 0.3, -1>, <1, 2, 0> }
  translate <-1.4, 0, -1.2> pigment { rgb <0.8, 0.5, 0.9> }
}
sor { 5, <0.2, -0.5>, <0.45, 0>, <0.35, 0.4>, <0.45, 0.8>, <0.3, 1.2>
  translate <1.2, 0, -1.4> uv_mapping pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.3, 0.9> scale <0.125, 0.25, 1> } }
