// text clipped by a sphere, and a sphere clipped by text (Point_In_Clip
// with the glyphs' inside test)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1, 1, -4> look_at <1, 0.3, 0> }
light_source { <-3, 6, -6> color rgb 1 }
plane { y, -0.5 pigment { rgb 0.85 } }
text { ttf "timrom.ttf" "Clip" 0.5, 0 clipped_by { sphere { <0.8, 0.3, 0>, 0.7 } } pigment { rgb <0.9,0.5,0.2> } }
sphere { <2.6, 0.3, 0>, 0.5 clipped_by { text { ttf "cyrvetic.ttf" "8" 2, 0 scale 1.5 translate <2.2, -0.3, -1> } } pigment { rgb <0.2,0.6,0.9> } }
