// A height field whose picture is not there: the picture's name is the
// error, not a crash or an empty field.
// expect: status 2
// expect: error height-field-missing-image.pov:6:20: cannot find the image 'no-such-heights.png' (looked in the current folder, the scene's folder and the include folders)
camera { location <0, 2, -3> look_at <0, 0, 0> }
height_field { png "no-such-heights.png" smooth pigment { rgb 1 } }
