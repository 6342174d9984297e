// contact.pov -- hard case 4: contact shadows and touching geometry.
// Boxes and cards rest on the floor (their bottom faces and edges lie in
// the floor's plane, so the receiver touches the occluder along the whole
// contact line); two boxes share part of a face (x = -1), a third rests on
// the taller one and overhangs the lower; a thin slab lies on the floor
// partly inside a box; a card leans against a box, touching it along an
// edge; a pyramid mesh stands on the floor; a triangle stands on one
// vertex; and the floor is two coplanar polygons meeting along x = 0 with a
// card lying flat on it across that seam (coplanar, overlapping: the card
// and the floor are the same material, so which one a camera ray reports
// does not change the colour, only which polygon the shadow test starts
// from). Stresses: points lying on a second polygon, shadow polygons
// starting exactly on the receiver, self-shadow at contact lines.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0.45, 4.6, -6.6> look_at <-0.3, 0.3, -0.5> angle 52 right x*4/3 }

light_source { <-3, 5, -2> color rgb <0.70, 0.66, 0.58> }
light_source { <4, 2.5, 1> color rgb <0.30, 0.34, 0.45> }

background { color rgb <0.08, 0.09, 0.12> }

// The floor: two coplanar polygons sharing the edge x = 0.
#declare Floor = texture { pigment { color rgb <0.78, 0.76, 0.72> } }
polygon { 5, <-6, 0, -5>, <0, 0, -5>, <0, 0, 6>, <-6, 0, 6>, <-6, 0, -5> texture { Floor } }
polygon { 5, <0, 0, -5>, <6, 0, -5>, <6, 0, 6>, <0, 0, 6>, <0, 0, -5> texture { Floor } }
// A card lying flat on the floor across the seam (same texture as the floor).
polygon { 5, <-0.5, 0, -2.5>, <0.75, 0, -2.5>, <0.75, 0, -1.5>, <-0.5, 0, -1.5>, <-0.5, 0, -2.5>
  texture { Floor } }
// A coloured block standing on that card (its bottom face in the plane of
// the card and of the floor).
box { <-0.2, 0, -2.2>, <0.4, 0.3, -1.8> pigment { color rgb <0.9, 0.6, 0.2> } }

// Two boxes sharing part of the face x = -1, and one resting on the taller.
box { <-2, 0, 0>, <-1, 1, 1> pigment { color rgb <0.25, 0.50, 0.80> } }
box { <-1, 0, 0>, <0, 0.75, 1> pigment { color rgb <0.80, 0.30, 0.25> } }
box { <-1.5, 1, 0.25>, <-0.5, 1.5, 0.75> pigment { color rgb <0.35, 0.70, 0.35> } }

// A card leaning against a box: its top edge lies on the box's face x = 1.
box { <1, 0, 0>, <1.6, 1.2, 0.8> pigment { color rgb <0.6, 0.6, 0.65> } }
polygon { 5, <0.25, 0, 0.1>, <1, 1, 0.1>, <1, 1, 0.7>, <0.25, 0, 0.7>, <0.25, 0, 0.1>
  pigment { color rgb <0.95, 0.90, 0.50> } }

// A pyramid mesh standing on the floor (its base edges on the floor).
mesh {
  triangle { <-0.5, 0, -0.5>, <0.5, 0, -0.5>, <0, 1, 0> }
  triangle { <0.5, 0, -0.5>, <0.5, 0, 0.5>, <0, 1, 0> }
  triangle { <0.5, 0, 0.5>, <-0.5, 0, 0.5>, <0, 1, 0> }
  triangle { <-0.5, 0, 0.5>, <-0.5, 0, -0.5>, <0, 1, 0> }
  pigment { color rgb <0.70, 0.45, 0.75> }
  translate <-2.5, 0, -1.5>
}
// A triangle standing on one vertex, its plane vertical.
triangle { <0, 0, 0>, <0.6, 1, 0>, <-0.6, 1, 0> pigment { color rgb <0.9, 0.9, 0.9> } translate <1.9, 0, -1.1> }
// A thin slab lying on the floor, partly inside the blue box (the solids overlap).
box { <-2.5, 0, -0.4>, <-1.2, 0.05, 0.4> pigment { color rgb <0.3, 0.3, 0.35> } }
