// A fisheye with the default angle (90) and right, turned (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { fisheye location <0.5, 2, -1> look_at <0, 0.5, 3> rotate y*20 }
#include "world.inc"
