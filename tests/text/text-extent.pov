// min_extent and max_extent of text and of CSG objects of text (POV-Ray's
// bounding box, carried through each transform): letters centred on the
// origin, as transforms.inc's Center_Trans and the sample scenes centre
// them, and shapes.inc's bevelled text (a union of text and an
// intersection of sheared copies) centred by Center_Object
#version 3.7;
#include "shapes.inc"
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
#declare C = Center_Object(Bevelled_Text("crystal.ttf", "POV", 3, 45, 0.025, 0.25, 0, no), x + y)
object { C pigment { rgb <0.3, 0.8, 0.3> } rotate -20 * y translate <1.2, 0.9, 0> }
#declare D = difference { object { C } text { ttf "timrom.ttf" "X" 2, 0 translate -z } rotate 30 * x }
object { Centred(D) pigment { rgb <0.8, 0.8, 0.3> } scale 0.8 translate <-1.3, -0.6, 0> }
sphere { 0, 0.05 pigment { rgb 1 } }
