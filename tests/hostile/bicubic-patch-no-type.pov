// A bicubic patch without its type: POV-Ray's error, where the type
// belongs.
// expect: status 2
// expect: error bicubic-patch-no-type.pov:6:17: Undefined bicubic patch type (give 'type 0' or 'type 1').
camera { location <0, 2, -3> look_at <0, 0, 0> }
bicubic_patch { flatness 0.1 <0, 0, 0>, <1, 0, 0> }
