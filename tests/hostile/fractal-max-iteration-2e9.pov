// A fractal pattern of 2e9 iterations a point, most of them inside the set:
// each colour takes seconds, so --max-render-seconds, checked between rays,
// came only after hours (POV-Ray renders on as long). The iterations now
// look at the deadline too: refused after the second.
// expect: status 2
// expect: option --max-render-seconds 1
camera { location <0, 0, -3> look_at 0 }
plane { z, 0 pigment { magnet 2 julia <0.3, 0.2>, 2000000000 } finish { ambient 1 } }
