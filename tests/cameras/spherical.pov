// A spherical camera, horizontal and vertical angles given (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical location <0, 1.5, 0> look_at <0, 1.2, 1> angle 300, 140 }
#include "world.inc"
