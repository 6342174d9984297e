// text in CSG: engraved into a box (difference), a box cut to the letters
// (intersection), text with a sphere taken away, a merge
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.6, 0> }
light_source { <-3, 6, -6> color rgb 1 }
plane { y, -1 pigment { rgb 0.85 } }
difference {
    box { <-2.2, -0.2, 0>, <2.2, 0.9, 0.6> }
    text { ttf "timrom.ttf" "Carve" 0.4, 0 translate <-1.3, 0, -0.1> }
    pigment { rgb <0.8, 0.7, 0.5> }
}
intersection {
    text { ttf "cyrvetic.ttf" "OX" 1, 0 scale 0.8 }
    box { <0, 0.2, 0.1>, <2, 2, 0.7> }
    pigment { rgb <0.3, 0.5, 0.9> }
    translate <-0.6, 1, -0.5>
}
difference {
    text { ttf "crystal.ttf" "8" 0.5, 0 }
    sphere { <0.3, 0.4, 0>, 0.3 }
    pigment { rgb <0.9, 0.3, 0.3> }
    translate <1.3, 1.1, -0.5>
}
merge {
    text { ttf "timrom.ttf" "m" 0.3, 0 }
    cylinder { <0.2, 0.2, -0.5>, <0.2, 0.2, 0.8>, 0.1 }
    pigment { rgbf <0.4, 0.9, 0.4, 0.5> }
    translate <-2.3, 1.1, -0.8>
}
