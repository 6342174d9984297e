// height_field { function W, H { ... } }: hstrace has no user functions;
// refused where it is written, not misread.
// expect: status 2
// expect: error height-field-function.pov:6:16: 'function' is not supported by hstrace
camera { location <0, 2, -3> look_at <0, 0, 0> }
height_field { function 64, 64 { x * y } }
