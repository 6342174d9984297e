// text seen front-on: Times (timrom.ttf, kerned "AV" and "Ta"), its
// shadow on the wall behind it
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.6, 0.35, -4> look_at <1.6, 0.35, 0> }
light_source { <-3, 5, -6> color rgb 1 }
plane { z, 0.6 pigment { rgb <0.8, 0.8, 0.7> } }
text { ttf "timrom.ttf" "POV-Ray AVTa" 0.3, 0 pigment { rgb <0.9, 0.3, 0.2> } translate <-0.4, 0, 0> }
