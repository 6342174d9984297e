// A fisheye of 200 degrees, its circle wider than tall (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { fisheye location <0, 1.5, 0> look_at <0, 1.2, 1> right x*4/3 angle 200 }
#include "world.inc"
