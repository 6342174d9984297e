// Two facing mirrors at POV-Ray's deepest max_trace_level, 256, with no
// bailout: the ray tree, walked recursively, is at its deepest (a
// max_trace_level of 1e10 is held to 256, with POV-Ray's warning).
// expect: status 0
global_settings { max_trace_level 1e10 adc_bailout 0 }
camera { location <0, 0, 0> look_at z }
light_source { <0, 0, 0>, 1 }
plane { z, 1 finish { reflection 1 } }
plane { -z, 1 finish { reflection 1 } }
