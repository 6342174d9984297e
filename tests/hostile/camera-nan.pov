// A camera at NaN (issue 22): refused at the value.
// expect: status 2
// expect: error camera-nan.pov:5:19: expected a finite vector, found <nan, 0, -5>
#declare N = 0 * 1e309;
camera { location <N, 0, -5> look_at 0 }
light_source { <0, 5, -5>, 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { rgb 1 } }
