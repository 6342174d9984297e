// fresnel 1e10 (issue 22): POV-Ray's "fresnel must be true or false".
// expect: status 2
// expect: error fresnel-1e10.pov:4:46: fresnel must be true or false
triangle { 0, x, y finish { reflection { 0.5 fresnel 1e10 } } }
