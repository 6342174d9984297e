// Cylinder camera 2, 200 degrees about right (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 2 location <0, 1.5, -1> look_at <0, 1.2, 1> right x*3 angle 200 }
#include "world.inc"
