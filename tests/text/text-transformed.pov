// text rotated, scaled unevenly and sheared, with an offset between the
// characters: Crystal (crystal.ttf) and a font given without its
// extension, laid along <0.1, 0.05, 0.3> (the z part is not applied)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.5, 0> }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 } }
text { ttf "crystal.ttf" "Mono 42" 0.5, <0.1, 0.05, 0.3>
       pigment { rgb <0.9, 0.8, 0.2> }
       scale <1.2, 2, 0.8> rotate <0, -30, 10> translate <-2.5, 0.3, 0> }
text { ttf "timrom" "Skew" 1.5, 0
       pigment { rgb <0.3, 0.8, 0.4> }
       matrix <1, 0, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0> rotate <-20, 40, 0> translate <0.8, 1.2, 1> }
