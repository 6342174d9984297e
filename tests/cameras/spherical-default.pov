// A spherical camera, its default 360 by 180 degrees, sky tilted (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical location <0, 1.5, 0> look_at <0, 1, 1> sky <0.2, 1, 0> angle 360 }
#include "world.inc"
