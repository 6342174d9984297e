// Coordinates beyond float's range (3.4e38), which are fine doubles: the
// hierarchy keeps its boxes in float, rounded outward, so these become
// infinite; binning an infinite centre gave NaN, converted to an int
// (undefined behaviour, found by the fuzzer). POV-Ray renders the scene:
// the near objects as usual, the far box out of sight.
// expect: status 0
camera { location <0, 1, -5> look_at 0 }
light_source { <2, 4, -3>, 1 }
polygon { 5, <-2, 0, -2>, <2, 0, -2>, <2, 0, 2>, <-2, 0, 2>, <-2, 0, -2> pigment { rgb 1 } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> pigment { rgb <1, 0, 0> } }
box { 0, 1 translate <0.5, 4e97, 0> pigment { rgb 1 } }
box { 0, 1 translate <-4e97, 0, 4e97> pigment { rgb 1 } }
triangle { <0, 0, 3>, <1e39, 1, 3>, <0, 1, 1e39> pigment { rgb <0, 1, 0> } }
