// A blob as a part of CSG: cut by a box (difference), intersected with a
// sphere, and an inverse blob in an intersection, so that every crossing
// and the blob's inside test count (tests/blob.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -5>, rgb 1 }
light_source { <4, 3, -6>, rgb 0.3 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
#declare B = blob {
  threshold 0.5
  sphere { <-0.6, 0, 0>, 1.2, 1 }
  sphere { <0.6, 0, 0>, 1.2, 1 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.6, 1 }
}
difference {
  object { B }
  box { <-2, 0.1, -2>, <0, 2, 2> }
  pigment { rgb <0.9, 0.5, 0.3> }
  translate <-1.8, 1, 0>
}
intersection {
  object { B }
  sphere { <0, 0, -0.3>, 1.1 }
  pigment { rgb <0.3, 0.8, 0.8> }
  translate <1.8, 1, 0>
}
intersection {
  box { <-0.8, 0, -0.8>, <0.8, 0.8, 0.8> }
  object { B scale 0.5 inverse translate <0, 0.4, 0> }
  pigment { rgb <0.9, 0.9, 0.4> }
  translate <0, 0, 1.5>
}
// a glass blob: the rays through it leave it by later crossings
blob {
  threshold 0.6
  sphere { <-0.4, 0, 0>, 0.8, 1 }
  sphere { <0.4, 0, 0>, 0.8, 1 }
  pigment { rgbf <1, 1, 1, 0.9> }
  interior { ior 1.4 }
  translate <0, 2.6, -1>
}
