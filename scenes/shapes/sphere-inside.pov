// The eye inside a sphere: a big sphere around the camera and a light,
// lit from within, a smaller sphere and a box casting shadows on its
// inside. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -2> look_at <0, 0, 0> angle 70 }
light_source { <1.5, 2, -1> color rgb 1 }
sphere { 0, 5 pigment { rgb <0.8, 0.75, 0.6> } }
sphere { <0.5, 0.2, 1>, 0.7 pigment { rgb <0.2, 0.5, 0.9> } }
box { <-1.5, -1, 0.5>, <-0.8, 0.2, 1.2> rotate 20 * y pigment { rgb <0.9, 0.4, 0.3> } }
