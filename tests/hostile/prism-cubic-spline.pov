// A prism of a curved spline: its sides are no planar pieces, so it is
// refused where the spline is named (the analytic shapes will render it).
// expect: status 2
// expect: error prism-cubic-spline.pov:6:9: 'cubic_spline' is not supported by hstrace
camera { location <0, 2, -3> look_at <0, 0, 0> }
prism { cubic_spline 0, 1, 6, <0, 0>, <1, 1>, <1, 0>, <0, 0>, <1, 1>, <1, 0> }
