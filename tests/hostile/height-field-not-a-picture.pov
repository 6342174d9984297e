// A height field given a file that is no picture (this scene): refused
// with the file's name at the name's position.
// expect: status 2
// expect: error height-field-not-a-picture.pov:6:20: height_field: cannot read './height-field-not-a-picture.pov': not an EXR, PNG, PPM, Targa, BMP, JPEG or HDR file
camera { location <0, 2, -3> look_at <0, 0, 0> }
height_field { pgm "height-field-not-a-picture.pov" water_level 0.2 }
