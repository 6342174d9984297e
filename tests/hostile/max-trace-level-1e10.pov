// max_trace_level 1e10 (issue 22: converted to int out of range). POV-Ray
// uses its limit, 256, with a warning; so does hstrace.
// expect: status 0
global_settings { max_trace_level 1e10 }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, -5>, 1 }
triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1, 0> pigment { rgb 1 } }
