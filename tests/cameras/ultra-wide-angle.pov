// An ultra_wide_angle camera of 170 degrees (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { ultra_wide_angle location <0, 1.5, 0> look_at <0, 1.2, 1> right x*4/3 angle 170 }
#include "world.inc"
