// Cylinder camera 3, rays from a line along up (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 3 location <0, 1.5, 0> look_at <0, 1.5, 1> up y*2.5 right x*4/3 angle 300 }
#include "world.inc"
