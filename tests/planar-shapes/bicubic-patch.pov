// Bicubic patches of both types, one subdivided by flatness and one by its
// steps alone, bent so that one shadows the other and the floor, placed by
// transforms; one uv-mapped with a checker (tests/planar-shapes.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 7, -3>, rgb 1 }
light_source { <5, 3, -6>, rgb 0.4 }
#macro Points()
  <0, 0, 0>, <1, 0.5, 0>, <2, -0.5, 0>, <3, 0, 0>,
  <0, 0.8, 1>, <1, 2.5, 1>, <2, 1.5, 1>, <3, 0.3, 1>,
  <0, 0.5, 2>, <1, 1.5, 2>, <2, 2.8, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 0.3, 3>, <2, 0.6, 3>, <3, 0, 3>
#end
bicubic_patch {
  type 0 flatness 0.01 u_steps 4 v_steps 4
  Points()
  translate <-3.2, 0, -1> rotate y * 15
  pigment { rgb <0.9, 0.6, 0.3> }
}
bicubic_patch {
  type 1 u_steps 3 v_steps 2
  Points()
  scale <0.9, 1.2, 0.8> rotate <0, -30, 10> translate <0.8, 0.2, -0.5>
  uv_mapping pigment { checker rgb <0.3, 0.6, 0.9>, rgb <0.9, 0.9, 0.8> scale 0.25 }
}
plane { y, -0.3 pigment { rgb <0.5, 0.55, 0.5> } }
