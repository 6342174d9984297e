// A prism whose count of points is no count: refused at the count, before
// any memory is asked for.
// expect: status 2
// expect: error prism-count-garbage.pov:6:15: prism: 1e+300 is not a usable number of points
camera { location <0, 2, -3> look_at <0, 0, 0> }
prism { 0, 1, 1e300, <0, 0>, <1, 1>, <1, 0> }
