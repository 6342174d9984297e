// far-coordinates.pov -- hard case 6: far from the origin, small beside large.
// Everything (camera, lights, objects) is translated by O = <1e5, 1e5, 1e5>,
// where a double's spacing is about 1.5e-11 and a float's about 0.008.
// Objects of size 0.01 (a cluster of little cubes, cards and a holed card
// 0.02 across, a 0.005 gap between two cubes) stand beside objects of
// size 10: a wall, 6.4 away, whose shadow edge from the main light runs
// through the cluster, and a slab on legs; the camera stands 0.65 from the
// little ones. Stresses: tolerances relative to the scene size, crossings
// and hit points computed as small differences of large coordinates, tiny
// shadow polygons in large grid cells.
#version 3.7;
global_settings { assumed_gamma 1 }

// POV-Ray's own renders at 1e5 show artefacts of its single-precision
// bounding boxes, so its reference is rendered at the origin, where it is
// exact; hstrace renders the scene as it stands, at 1e5.
// povray-reference-options: Declare=Offset=0
#ifndef (Offset)
#declare Offset = 100000;
#end
#declare O = <1, 1, 1> * Offset;

camera { location O + <0.12, 0.32, -0.55> look_at O + <0.01, 0, 0.04> angle 55 right x*4/3 }

light_source { O + <-14, 22, -9> color rgb <0.70, 0.66, 0.58> }
light_source { O + <9, 6, -4> color rgb <0.30, 0.34, 0.45> }
light_source { O + <-30, 50, 100> color rgb <0.15, 0.15, 0.15> parallel point_at O }

background { color rgb <0.08, 0.09, 0.12> }

polygon { 5, <-30, 0, -30>, <30, 0, -30>, <30, 0, 30>, <-30, 0, 30>, <-30, 0, -30>
  pigment { color rgb <0.78, 0.76, 0.72> } translate O }

// Large: a wall 10 x 10 (its top edge's shadow falls at x = 0.007) and a
// slab 10 x 10 on four legs.
box { <-6.86, 0, -9>, <-6.36, 10, 1> pigment { color rgb <0.45, 0.55, 0.70> } translate O }
union {
  box { <0, 1.2, 0>, <10, 1.4, 10> }
  box { <0, 0, 0>, <0.3, 1.2, 0.3> }
  box { <9.7, 0, 0>, <10, 1.2, 0.3> }
  box { <0, 0, 9.7>, <0.3, 1.2, 10> }
  box { <9.7, 0, 9.7>, <10, 1.2, 10> }
  pigment { color rgb <0.70, 0.45, 0.30> }
  translate O + <0.2, 0, 0.5>
}

// Small: cubes of 0.01 to 0.04, two of them 0.005 apart, on the floor.
#declare Cube = box { <0, 0, 0>, <0.01, 0.01, 0.01> }
object { Cube pigment { color rgb <0.9, 0.2, 0.2> } translate O + <-0.05, 0, 0> }
object { Cube pigment { color rgb <0.2, 0.8, 0.2> } translate O + <-0.035, 0, 0> }
object { Cube pigment { color rgb <0.2, 0.3, 0.9> } scale 2 translate O + <0.02, 0, -0.02> }
object { Cube pigment { color rgb <0.9, 0.8, 0.2> } scale 4 rotate y*30 translate O + <0.07, 0, 0.05> }
object { Cube pigment { color rgb <0.8, 0.4, 0.8> } scale <1, 6, 1> translate O + <-0.01, 0, 0.08> }
// A card 0.02 x 0.015 standing on the floor and a holed card above it.
polygon { 5, <0, 0>, <0.02, 0>, <0.02, 0.015>, <0, 0.015>, <0, 0>
  pigment { color rgb <0.95, 0.95, 0.9> } rotate y*-20 translate O + <-0.09, 0, 0.04> }
polygon { 10,
  <-0.01, -0.01>, <0.01, -0.01>, <0.01, 0.01>, <-0.01, 0.01>, <-0.01, -0.01>,
  <-0.005, -0.005>, <0.005, -0.005>, <0.005, 0.005>, <-0.005, 0.005>, <-0.005, -0.005>
  pigment { color rgb <0.3, 0.8, 0.8> } rotate x*90 translate O + <0.0, 0.03, 0.12> }
// A triangle 0.03 across lying on the floor, and a tilted one standing.
triangle { <0, 0, 0>, <0.03, 0, 0>, <0.01, 0, 0.02> pigment { color rgb <0.2, 0.2, 0.2> } translate O + <0.03, 0, -0.07> }
triangle { <0, 0, 0>, <0.03, 0, 0>, <0.015, 0.025, 0.008> pigment { color rgb <0.9, 0.5, 0.1> } translate O + <-0.08, 0, -0.05> }
