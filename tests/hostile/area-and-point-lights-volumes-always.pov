// Found by fuzzing (make fuzz, the scene entry point): a point light and an
// area light with --volumes always. The cost model times the gathering of
// the point light's shadow polygons with a shadow context of no method,
// which asked that method (NULL) whether it casts area beams for the area
// light: a segmentation fault before anything was drawn.
// expect: status 0
// expect: option --volumes always
camera { location <0, 2, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3>, rgb 1 }
light_source { <-3, 5, -3>, rgb 0.5 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
plane { y, 0 pigment { rgb 1 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb 1 } }
