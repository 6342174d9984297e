// An omnimax camera, its dome cut below 45 degrees (tests/cameras.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { omnimax location <0, 1.5, 0> look_at <0, 2, 1> right x*4/3 angle 180 }
#include "world.inc"
