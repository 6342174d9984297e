// A camera at +-1e308 (issue 22: grid_walk_begin converted its cell out of
// range). The values are finite: POV-Ray renders the scene, and so does hstrace.
// expect: status 0
camera { location <-1e308, 1e308, -1e308> look_at 0 }
light_source { <0, 5, -5>, 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { rgb 1 } }
