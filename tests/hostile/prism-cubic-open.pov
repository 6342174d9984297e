// A cubic prism whose outline never closes: POV-Ray warns that it ignores
// it, then its Compute_Prism runs past the last point, a fatal "Too few
// points in prism." (here at the count).
// expect: status 2
// expect: error prism-cubic-open.pov:7:28: Too few points in prism.
camera { location <0, 2, -3> look_at <0, 0, 0> }
prism { cubic_spline 0, 1, 7, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0.5>, <2, 2>, <3, 3> }
