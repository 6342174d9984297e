// degenerate.pov -- hard case 9: degenerate and non-manifold geometry.
//  - a zig-zag strip of cards (a mesh) whose triangles alternate their
//    winding, so neighbouring faces disagree about which side is "front"
//    (POV-Ray's triangles are two-sided; the winding only orients normals);
//  - two identical cards on top of each other with opposite winding (same
//    texture, so which one a ray reports does not change the colour);
//  - zero-area triangles: collinear vertices and a repeated vertex, inside
//    a mesh and on their own, along the edges of a real card;
//  - three quads meeting on one edge (a paddle wheel: the edge is shared by
//    three faces, and by a fourth, coplanar with one of them);
//  - a polygon with a hole, and one with a repeated vertex and a vertex in
//    the middle of a straight side.
// Stresses: silhouette detection and edge cancellation when windings are
// mixed, edges are shared by 3 or 4 faces, faces coincide, or have no area.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0.55, 4.4, -6.6> look_at <-0.3, 0.5, 0.3> angle 56 right x*4/3 }

light_source { <-3, 6, -2.5> color rgb <0.70, 0.66, 0.58> }
light_source { <4, 3.5, 1> color rgb <0.30, 0.34, 0.45> }

background { color rgb <0.08, 0.09, 0.12> }
polygon { 5, <-8, 0, -6>, <8, 0, -6>, <8, 0, 8>, <-8, 0, 8>, <-8, 0, -6>
  pigment { color rgb <0.78, 0.76, 0.72> } }

// A zig-zag strip of three panels, raised on its low edge. Every second
// triangle is wound the other way, so every shared edge (the panels'
// diagonals and folds) joins two faces of opposite winding.
mesh {
  triangle { <0, 0.3, 0>,   <0.5, 0.3, 0>,   <0.5, 1, 0.4> }
  triangle { <0, 0.3, 0>,   <0, 1, 0.4>,     <0.5, 1, 0.4> }    // the other way
  triangle { <0.5, 0.3, 0>, <1, 0.3, 0.3>,   <1, 1, 0.7> }
  triangle { <0.5, 0.3, 0>, <0.5, 1, 0.4>,   <1, 1, 0.7> }      // the other way
  triangle { <1, 0.3, 0.3>, <1.5, 0.3, 0>,   <1.5, 1, 0.4> }
  triangle { <1, 0.3, 0.3>, <1, 1, 0.7>,     <1.5, 1, 0.4> }    // the other way
  pigment { color rgb <0.80, 0.40, 0.25> }
  translate <-3.2, 0, -0.5>
}
// Legs for the strip (thin cards down to the floor).
polygon { 4, <0, 0>, <0.5, 0>, <0, 0.3>, <0, 0> pigment { color rgb 0.5 } translate <-3.2, 0, -0.5> }
polygon { 4, <1.5, 0>, <1.0, 0>, <1.5, 0.3>, <1.5, 0> pigment { color rgb 0.5 } translate <-3.2, 0, -0.5> }

// Two coincident cards, opposite winding, held up at an angle.
#declare Card = texture { pigment { color rgb <0.30, 0.55, 0.80> } }
polygon { 5, <-0.6, 0, 0>, <0.6, 0, 0>, <0.6, 0.9, 0>, <-0.6, 0.9, 0>, <-0.6, 0, 0>
  texture { Card } rotate x*-25 translate <-0.8, 0.25, -1.6> }
polygon { 5, <-0.6, 0, 0>, <-0.6, 0.9, 0>, <0.6, 0.9, 0>, <0.6, 0, 0>, <-0.6, 0, 0>
  texture { Card } rotate x*-25 translate <-0.8, 0.25, -1.6> }
triangle { <-0.6, 0, 0>, <0.6, 0, 0>, <0, 0.25, 0.4> texture { Card } translate <-0.8, 0, -1.6> }

// A card on a stand, with zero-area triangles along its edges and inside:
// collinear vertices (on an edge and across the middle) and a repeated
// vertex.
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <1, 0.8, 0> }
  triangle { <0, 0, 0>, <1, 0.8, 0>, <0, 0.8, 0> }
  triangle { <0, 0, 0>, <0.5, 0, 0>, <1, 0, 0> }          // on the bottom edge
  triangle { <0, 0, 0>, <0.5, 0.4, 0>, <1, 0.8, 0> }      // on the diagonal
  triangle { <0, 0.8, 0>, <0, 0.8, 0>, <1, 0.8, 0> }      // repeated vertex
  pigment { color rgb <0.35, 0.70, 0.35> }
  rotate x*-60 translate <0.6, 0.7, -0.3>
}
triangle { <0.6, 0.7, -0.3>, <1.6, 0.7, -0.3>, <1.1, 0.7, -0.3> pigment { color rgb 0.9 } }  // on its own, collinear
box { <0.6, 0, -0.35>, <1.6, 0.7, -0.3> pigment { color rgb 0.45 } }

// A paddle wheel: three quads on the edge x = 0..1.2 at y = 0.6, z = 2,
// plus a fourth face coplanar with the first, sharing the same edge.
union {
  polygon { 5, <0, 0, 0>, <1.2, 0, 0>, <1.2, 0.6, 0>, <0, 0.6, 0>, <0, 0, 0> rotate x*0 }
  polygon { 5, <0, 0, 0>, <1.2, 0, 0>, <1.2, 0.6, 0>, <0, 0.6, 0>, <0, 0, 0> rotate x*120 }
  polygon { 5, <0, 0, 0>, <1.2, 0, 0>, <1.2, 0.6, 0>, <0, 0.6, 0>, <0, 0, 0> rotate x*240 }
  polygon { 5, <0, 0, 0>, <1.2, 0, 0>, <1.2, -0.5, 0>, <0, -0.5, 0>, <0, 0, 0> }
  pigment { color rgb <0.85, 0.75, 0.30> }
  translate <1.4, 0.6, 1.6>
}

// A polygon with a hole, tilted over the floor.
polygon { 10,
  <-0.7, -0.5>, <0.7, -0.5>, <0.7, 0.5>, <-0.7, 0.5>, <-0.7, -0.5>,
  <-0.3, -0.2>, <0.3, -0.2>, <0.3, 0.25>, <-0.3, 0.25>, <-0.3, -0.2>
  pigment { color rgb <0.70, 0.45, 0.75> }
  rotate x*70 translate <-1.4, 0.9, 1.6> }
// A polygon with a repeated vertex and a vertex in the middle of a side.
polygon { 7, <0, 0>, <0.5, 0>, <1, 0>, <1, 0.6>, <1, 0.6>, <0, 0.6>, <0, 0>
  pigment { color rgb <0.9, 0.9, 0.9> } rotate x*90 translate <2.0, 0.5, -1.6> }
box { <2.45, 0, -1.35>, <2.55, 0.5, -1.25> pigment { color rgb 0.45 } }
