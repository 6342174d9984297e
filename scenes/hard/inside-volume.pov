// inside-volume.pov -- hard case 5: the eye and the lights inside shadow
// volumes.
// The camera stands in the shadow of two occluders above and behind it (a
// roof and a card above the roof, both out of view), so its depth count
// for the main light starts at 2, not 0. A second point light stands low
// among objects, inside the scene's bounds, surrounded by a ring of blocks
// and a leaning card. A third light is shut inside a closed box (six faces
// around it), so it lights nothing outside: every point outside the box is
// in its shadow, and the eye's count for it is 1. Stresses: non-zero depth
// counts at the eye, lights inside the grid, shadow volumes that enclose
// their light, counts carried from pixel to pixel starting in shadow.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0.35, 1.9, -3.6> look_at <-0.3, 0.3, 1.4> angle 55 right x*4/3 }

light_source { <0.5, 6, -3> color rgb <0.65, 0.62, 0.55> }     // above the roof
light_source { <0.25, 0.55, 1.5> color rgb <0.45, 0.40, 0.30> } // among the blocks
light_source { <-2.5, 0.5, 2.5> color rgb <0.9, 0.9, 0.9> }    // shut in a box

background { color rgb <0.08, 0.09, 0.12> }

polygon { 5, <-6, 0, -8>, <6, 0, -8>, <6, 0, 7>, <-6, 0, 7>, <-6, 0, -8>
  pigment { color rgb <0.78, 0.76, 0.72> } }

// The roof over the camera and a card above it.
polygon { 5, <-3, 3, -6>, <3, 3, -6>, <3, 3, -2.5>, <-3, 3, -2.5>, <-3, 3, -6>
  pigment { color rgb <0.5, 0.5, 0.5> } }
polygon { 5, <-1, 4.5, -3.8>, <1.5, 4.5, -3.8>, <1.5, 4.5, -2.8>, <-1, 4.5, -2.8>, <-1, 4.5, -3.8>
  pigment { color rgb <0.5, 0.5, 0.5> } }

// A ring of blocks around the low light, and a card leaning over it.
#declare Block = box { <-0.2, 0, -0.2>, <0.2, 0.8, 0.2> }
object { Block pigment { color rgb <0.8, 0.3, 0.2> } translate <1.25, 0, 1.5> }
object { Block pigment { color rgb <0.2, 0.6, 0.3> } rotate y*30 translate <0.75, 0, 2.4> }
object { Block pigment { color rgb <0.3, 0.4, 0.8> } rotate y*-20 translate <-0.6, 0, 2.0> }
object { Block pigment { color rgb <0.8, 0.7, 0.2> } translate <-0.6, 0, 0.9> }
object { Block pigment { color rgb <0.6, 0.3, 0.7> } rotate y*45 translate <0.55, 0, 0.35> }
polygon { 5, <-0.6, 0, 0>, <0.6, 0, 0>, <0.6, 1.0, 0.5>, <-0.6, 1.0, 0.5>, <-0.6, 0, 0>
  pigment { color rgb <0.9, 0.9, 0.85> } translate <0.2, 0, 2.6> }

// The closed box with a light inside.
box { <-3, 0, 2>, <-2, 1, 3> pigment { color rgb <0.35, 0.55, 0.75> } }
// Something beside it to receive (no) light from it.
box { <-1.8, 0, 1.3>, <-1.4, 1.4, 1.7> pigment { color rgb <0.85, 0.85, 0.85> } }
