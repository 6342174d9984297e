// min_extent and max_extent of text (POV-Ray's bounding box, carried
// through each transform): letters centred on the origin, as
// transforms.inc's Center_Trans and the sample scenes centre them
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -4> look_at 0 }
light_source { <-2, 4, -5> color rgb 1 }
plane { z, 1 pigment { rgb 0.8 } }
#macro Centred(Obj)
    #local Mn = min_extent(Obj);
    #local Mx = max_extent(Obj);
    object { Obj translate -(Mn + (Mx - Mn) / 2) }
#end
#declare A = text { ttf "cyrvetic.ttf" "Centre" 0.5, 0 scale <0.7, 0.7, 1> rotate 25 * y }
#declare B = text { ttf "timrom.ttf" "Wg" 1, <0.1, 0, 0> rotate <-30, 0, 15> }
object { Centred(A) pigment { rgb <0.9, 0.4, 0.2> } translate 0.5 * y }
object { Centred(B) pigment { rgb <0.2, 0.5, 0.9> } scale 0.6 translate -0.6 * y }
sphere { 0, 0.05 pigment { rgb 1 } }
