// A linear prism of two points: POV-Ray's own message, at the count.
// expect: status 2
// expect: error prism-two-points.pov:5:29: Prism with linear splines must have at least three points.
camera { location <0, 2, -3> look_at <0, 0, 0> }
prism { linear_spline 0, 1, 2, <0, 0>, <1, 1> }
