// text met at grazing angles: the front face seen almost edge-on, the
// walls of curves and lines lit from the side (cyrvetic.ttf, kerned)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-1.5, 0.45, -0.35> look_at <1.5, 0.35, 0> angle 50 }
light_source { <-2, 6, -3> color rgb 1 }
light_source { <6, 1, -0.05> color rgb 0.5 }
plane { y, 0 pigment { rgb <0.7, 0.75, 0.8> } }
text { ttf "cyrvetic.ttf" "Graze WAVy" 0.2, 0 pigment { rgb <0.2, 0.6, 0.9> } }
