// A panoramic camera, sky and floor at its top and bottom rows (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { panoramic location <0, 1.5, 0> look_at <0, 1.5, 1> right x*4/3 }
#include "world.inc"
