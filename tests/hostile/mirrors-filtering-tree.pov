// The three reflecting, filtering planes of mirrors-filtering.pov with no
// option at all (issue 39): one camera ray's tree would be 2^256 rays.
// The default --max-tree-rays (2^20) stops it within about a second,
// whatever the thread count, and no image is written.
// expect: status 2
global_settings { max_trace_level 256 adc_bailout 0 }
camera { location <0, 0, 0> look_at <1, 0, 1> }
light_source { <0, 0, 0>, 1 }
plane { z, -1 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
plane { z, 1 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
plane { z, 3 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
