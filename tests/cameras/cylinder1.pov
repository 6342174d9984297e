// Cylinder camera 1, 270 degrees about up (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 1 location <0, 1.5, 0> look_at <0, 1.2, 1> up y*1.5 angle 270 }
#include "world.inc"
