// thick and thin: a slab of 2 units, a sheet of 0.01, and the built-in
// fonts (internal 0 to 3: povlogo, timrom, cyrvetic, crystal)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2, 3, -5> look_at <2, 0.8, 0> }
light_source { <-3, 7, -5> color rgb 1 }
plane { y, -0.01 pigment { rgb 0.8 } }
text { internal 1 "Thick" 2, 0 pigment { rgb <0.8, 0.4, 0.3> } rotate <-90, 0, 0> translate <-1, 0, 2> }
text { internal 2 "thin" 0.01, 0 pigment { rgb <0.4, 0.4, 0.9> } translate <0.2, 0.2, -1> }
text { internal 3 "Cr" 0.3, 0 pigment { rgb <0.9, 0.9, 0.4> } translate <3, 0.8, -1> }
text { internal 0 "PO" 0.3, 0 pigment { rgb <0.5, 0.9, 0.5> } translate <3.2, 0, -1.5> }
