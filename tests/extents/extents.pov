// min_extent and max_extent of each kind of object hstrace keeps POV-Ray's
// bounding box for, through the transforms that kind takes into its own
// parameters and those it keeps apart; and transforms.inc's Center_Trans
// and Align_Trans, which are made of them. Every line is written to
// extents.txt, for tests/extents.sh to compare with POV-Ray's.
#version 3.7;
#include "transforms.inc"
#fopen Out "extents.txt" write
#macro Show(Name, O)
  #write(Out, Name, " ", vstr(3, min_extent(O), " ", 0, 9), " ", vstr(3, max_extent(O), " ", 0, 9), "\n")
#end
Show("sphere", sphere { <1, 2, 3>, 0.5 })
Show("sphere-translated", sphere { <1, 2, 3>, 0.5 translate <1, 1, 1> })
Show("sphere-rotated", sphere { <1, 2, 3>, 0.5 rotate <30, 40, 50> })
Show("sphere-rotated-twice", sphere { <1, 2, 3>, 0.5 rotate 30 * x rotate 70 * y })
Show("sphere-scaled", sphere { <1, 2, 3>, 0.5 scale -3 })
Show("sphere-ellipsoid", sphere { <1, 2, 3>, 0.5 scale <1, 2, 3> })
Show("sphere-ellipsoid-rotated", sphere { <1, 2, 3>, 0.5 scale <1, 2, 3> rotate 30 * z rotate 20 * x })
Show("sphere-rotated-ellipsoid", sphere { <1, 2, 3>, 0.5 rotate 30 * z scale <1, 2, 3> })
Show("sphere-matrix", sphere { 0, 1 matrix <1, 0.5, 0, 0, 1, 0, 0, 0, 1, 2, 3, 4> })
Show("box", box { <1, 2, 3>, <-1, -2, -3> })
Show("box-moved", box { <-1, -2, -3>, <1, 2, 3> scale <2, -1, 3> translate x })
Show("box-rotated", box { <-1, -2, -3>, <1, 2, 3> rotate 30 * y })
Show("box-rotated-twice", box { <-1, -2, -3>, <1, 2, 3> rotate 30 * y rotate 40 * x translate 1 })
Show("cylinder", cylinder { <0, 0, 0>, <1, 2, 3>, 0.5 })
Show("cylinder-reversed", cylinder { <1, 2, 3>, <0, 0, 0>, 0.5 })
Show("cylinder-up", cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 open })
Show("cylinder-rotated", cylinder { <0, 0, 0>, <1, 2, 3>, 0.5 rotate 30 * x scale <1, 2, 1> })
Show("cone", cone { <0, 0, 0>, 1, <0, 3, 0>, 0.25 })
Show("cone-slanted", cone { <0, 0, 0>, 1, <1, 3, 2>, 0.25 rotate 10 * x })
Show("cone-reversed", cone { <1, 2, 3>, 0.25, <0, 0, 0>, 1 })
Show("cone-equal-radii", cone { <0, 0, 0>, 0.5, <1, 2, 3>, 0.5 })
Show("torus", torus { 2, 0.5 })
Show("torus-rotated", torus { 2, 0.5 rotate 45 * x rotate 30 * z translate 1 })
Show("disc", disc { <1, 1, 1>, <0, 1, 0>, 2 })
Show("disc-slanted", disc { <1, 1, 1>, <1, 1, 0>, 2, 0.5 })
Show("triangle", triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 2> })
Show("triangle-rotated", triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 2> rotate 20 * y })
Show("smooth-triangle", smooth_triangle { <0, 0, 0>, y, <1, 0, 0>, y, <0, 1, 2>, y scale 2 })
Show("mesh", mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 2> } triangle { <0, 0, 0>, <-1, 0, 0>, <0, -1, -2> } })
Show("mesh-rotated", mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 2> } triangle { <0, 0, 0>, <-1, 0, 0>, <0, -1, -2> } rotate 30 * x rotate 10 * y })
Show("mesh2", mesh2 { vertex_vectors { 4, <0, 0, 0>, <2, 0, 0>, <0, 3, 0>, <0, 0, 4> } face_indices { 2, <0, 1, 2>, <0, 1, 3> } rotate 15 * z })
Show("polygon", polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> })
Show("polygon-rotated", polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> rotate 30 * x translate 2 })
Show("plane", plane { y, 1 rotate 10 * x })
Show("superellipsoid", superellipsoid { <0.5, 0.5> scale 2 rotate 30 * y })
Show("union", union { sphere { 0, 1 } box { 1, 2 } })
Show("union-rotated", union { sphere { 0, 1 } box { 1, 2 } rotate 45 * y })
Show("intersection", intersection { sphere { 0, 1 } box { 0, 2 } })
#declare Ellipsoid = sphere { 0, 1 scale <1, 2, 1> }
Show("copy", object { Ellipsoid rotate 45 * z })
#declare Turned = box { -1, 1 rotate 30 * y }
Show("copy-turned-again", object { Turned rotate 30 * x })
Show("original-after-copy", Turned)
#declare Thing = union { sphere { <1, 2, 3>, 1 } cylinder { <1, 2, 3>, <4, 2, 0>, 0.5 } }
Show("center-trans", object { Thing Center_Trans(Thing, x + y + z) })
Show("align-trans", object { Thing Align_Trans(Thing, -y, <0, 5, 0>) })
Show("mesh-at-origin", mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 2> } })
Show("polygon-flat-x", polygon { 4, <0, 0, 0>, <0, 1, 0>, <0, 1, 1>, <0, 0, 0> })
#fclose Out
