// Cylinder camera 4, rays from a line along right (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 4 location <0, 1.5, 0> look_at <0, 1.5, 1> right x*4 angle 220 }
#include "world.inc"
