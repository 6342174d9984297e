// Infinite coordinates (issue 22: 1/0 and 1e309 rendered silently with status 0).
// POV-Ray takes them; hstrace refuses them at the value.
// expect: status 2
// expect: error geometry-infinite.pov:7:35: expected a finite vector, found <0, inf, 0>
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, -5>, 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1/0, 0> pigment { rgb 1 } }
