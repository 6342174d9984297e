// before #version 3.5 a byte above 127 is a character of its own (its
// code in the font's Macintosh map), not a space
#version 3.1;
global_settings { assumed_gamma 1 }
camera { location <1.8, 0.4, -4> look_at <1.8, 0.4, 0> }
light_source { <-3, 5, -6> color rgb 1 }
plane { z, 0.5 pigment { rgb 0.8 } }
text { ttf "timrom.ttf" "Grüße Ça" 0.2, 0 pigment { rgb <0.9, 0.7, 0.1> } }
#version 3.7;
