// holes.pov -- polygons with holes casting shadows with holes on a plane.
// POV-Ray polygons hold several closed outlines; a point is inside when it
// is inside an odd number of them, so later outlines cut holes.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0, 3.2, -7.5> look_at <0, 1.0, 0.5> angle 48 right x*4/3 }
light_source { <-3, 7, -4> color rgb <0.85, 0.82, 0.75> }
light_source { <5, 4, -2> color rgb <0.35, 0.38, 0.50> parallel point_at <0, 0, 0> }
background { color rgb <0.10, 0.12, 0.18> }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.66> } }

// A picture frame: a square with a square hole
polygon { 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
  <-0.7, -0.7>, <0.7, -0.7>, <0.7, 0.7>, <-0.7, 0.7>, <-0.7, -0.7>
  pigment { color rgb <0.80, 0.25, 0.15> }
  finish { phong 0.4 }
  rotate y*-25 translate <-2.1, 1.3, 0.8>
}

// A stencil: a plate with letter-like holes, one hole holding an island
#declare R = 0.18;
polygon { 5 + 5 + 5 + 7 + 5 + 5,
  <-1.4, -0.8>, <1.4, -0.8>, <1.4, 0.8>, <-1.4, 0.8>, <-1.4, -0.8>,
  // an "I"
  <-1.1, -0.5>, <-0.9, -0.5>, <-0.9, 0.5>, <-1.1, 0.5>, <-1.1, -0.5>,
  // an "O": outer hole ...
  <-0.6, -0.5>, <0.0, -0.5>, <0.0, 0.5>, <-0.6, 0.5>, <-0.6, -0.5>,
  // an "L"
  <0.25, -0.5>, <0.85, -0.5>, <0.85, -0.3>, <0.45, -0.3>, <0.45, 0.5>, <0.25, 0.5>, <0.25, -0.5>,
  // ... and the island inside the "O" (inside the hole: solid again)
  <-0.45, -0.3>, <-0.15, -0.3>, <-0.15, 0.3>, <-0.45, 0.3>, <-0.45, -0.3>,
  // a small window
  <1.0, 0.2>, <1.25, 0.2>, <1.25, 0.5>, <1.0, 0.5>, <1.0, 0.2>
  pigment { color rgb <0.20, 0.45, 0.70> }
  rotate x*-10 rotate y*12 translate <0.9, 1.6, 1.2>
}

// A lying grating: a plate with a row of slots, held above the floor
#declare Slots = 6;
polygon { 5 + 5*Slots,
  <-1.2, -0.5>, <1.2, -0.5>, <1.2, 0.5>, <-1.2, 0.5>, <-1.2, -0.5>
  #declare i = 0;
  #while (i < Slots)
    #declare x0 = -1.0 + i*0.35;
    , <x0, -0.35>, <x0 + 0.2, -0.35>, <x0 + 0.2, 0.35>, <x0, 0.35>, <x0, -0.35>
    #declare i = i + 1;
  #end
  pigment { color rgb <0.85, 0.80, 0.35> }
  rotate x*90 translate <-0.4, 0.45, -1.2>
}
// its two supports, stopping just under the plate (coplanar faces would z-fight)
box { <-0.05, 0, -0.05>, <0.05, 0.449, 0.05> pigment { color rgb 0.4 } translate <-1.5, 0, -1.2> }
box { <-0.05, 0, -0.05>, <0.05, 0.449, 0.05> pigment { color rgb 0.4 } translate < 0.7, 0, -1.2> }
