// A bicubic patch of 3 of its 16 points: the missing fourth is the error.
// expect: status 2
// expect: error bicubic-patch-three-points.pov:5:56: expected a numeric expression, found '}'
camera { location <0, 2, -3> look_at <0, 0, 0> }
bicubic_patch { type 1 <0, 0, 0>, <1, 0, 0>, <2, 0, 0> }
