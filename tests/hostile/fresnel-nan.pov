// fresnel NaN (issue 22): refused at the value.
// expect: status 2
// expect: error fresnel-nan.pov:5:54: expected a finite number, found nan
#declare N = 0 * 1e309;
triangle { 0, x, y finish { reflection { 0.5 fresnel N } } }
