// the default charset (ascii): bytes above 127 become spaces, and the
// Macintosh character map is read first
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.8, 0.4, -4> look_at <1.8, 0.4, 0> }
light_source { <-3, 5, -6> color rgb 1 }
plane { z, 0.5 pigment { rgb 0.8 } }
text { ttf "timrom.ttf" "Grüße Ça\tÅ" 0.2, 0 pigment { rgb <0.9, 0.7, 0.1> } }
