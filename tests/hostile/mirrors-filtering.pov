// Three reflecting, filtering planes with POV-Ray's deepest trace level and
// no bailout (issue 39): every ray between them splits in two, reflected
// and filtered, 256 levels deep, so one pixel is a tree of 2^256 rays. It
// rendered for ever (POV-Ray crashes); with the ray tree's budget off,
// --max-render-seconds stops every thread within a thousand rays of its
// time, and no image is written (mirrors-filtering-tree.pov: the tree's
// budget, on by default).
// expect: status 2
// expect: option --max-render-seconds 1 --max-tree-rays 0
global_settings { max_trace_level 256 adc_bailout 0 }
camera { location <0, 0, 0> look_at <1, 0, 1> }
light_source { <0, 0, 0>, 1 }
plane { z, -1 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
plane { z, 1 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
plane { z, 3 pigment { rgbf <1, 1, 1, 1> } finish { reflection 1 } }
