// A small scene: the seed of the image readers' corpora (rendered by
// hstrace to EXR, PNG and PPM) and of the scene's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -3>, rgb 1 }
plane { y, 0 pigment { checker rgb <1, 0.2, 0.2>, rgb 1 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgbt <0.2, 0.4, 1, 0.3> } finish { reflection 0.2 } }
triangle { <1, 0, 0>, <2, 0, 0>, <1.5, 1.5, 0> pigment { hexagon rgb 0, rgb 0.5, rgb 1 scale 0.2 } }
