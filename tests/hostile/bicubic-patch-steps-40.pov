// A bicubic patch of u_steps 40 and v_steps 40 would be 2^81 triangles:
// the world's memory budget refuses it at the patch, counted before
// anything is built.
// expect: status 2
// expect: option --max-memory 1G
// expect: error bicubic-patch-steps-40.pov:9:1: the world built from the scene would take 16 EiB (2417851639229258349412352 polygons) with this object, more than the memory budget of 1 GiB (--max-memory sets it)
camera { location <0, 2, -5> look_at <0, 0, 0> }
light_source { <1, 2, -3>, rgb 1 }
bicubic_patch { type 0 u_steps 40 v_steps 40
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 1, 0>, <1, 1, 1>, <2, 1, 1>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 1>, <2, 2, 1>, <3, 2, 0>, <0, 3, 0>, <1, 3, 0>, <2, 3, 0>, <3, 3, 0>
  pigment { rgb 1 } }
