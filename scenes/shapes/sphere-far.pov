// Far coordinates: the sphere scene moved 10^5 units away, camera and
// lights with it. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare F = <1e5, 2e5, -1e5>;
camera { location F + <0, 2, -6> look_at F + <0, 0.7, 0> angle 50 }
light_source { F + <4, 7, -3> color rgb 1 }
plane { y, F.y pigment { checker rgb 0.8, rgb 0.35 translate F } }
sphere { F + <0, 1, 0>, 1 pigment { rgb <0.9, 0.2, 0.1> } }
sphere { F + <-1.8, 0.5, 0.5>, 0.5 scale 1 pigment { rgb <0.2, 0.7, 0.25> } }
box { F + <1, 0, 0.5>, F + <2, 1.4, 1.5> pigment { rgb 0.75 } }
sphere { F + <1.5, 2.1, 1>, 0.35 pigment { rgb <0.6, 0.3, 0.8> } }
