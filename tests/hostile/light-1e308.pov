// A light 1e308 away: the direction toward it underflows to zero, and the
// shadow ray's grid walk stepped in place for ever (issue 22's camera at 1e308,
// for lights). POV-Ray renders it; so does hstrace.
// expect: status 0
camera { location <0, 0, -5> look_at 0 }
light_source { 1e308, 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { rgb 1 } }
