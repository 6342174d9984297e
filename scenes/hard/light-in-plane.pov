// light-in-plane.pov -- hard case 1: lights exactly in the plane of
// occluding polygons, and occluders seen exactly edge-on from a light.
// The low point light at <0, 1.5, 0> lies in the plane of: a shelf
// (y = 1.5), the top face of a box (so the box's silhouette from that light
// runs along an edge-on face), a card standing in the plane z = 0 (seen
// edge-on), the vertical half of a folded card (z = 0, its other half not
// edge-on, so the fold is a silhouette edge between an edge-on face and a
// lit one) and a triangle in the oblique plane x + y + z = 1.5. The
// parallel light's direction (1, -1, 0) lies in the planes z = constant, so
// the standing card and the folded card's vertical half are edge-on to it
// too. A third light, in no special plane, lights the rest. Floor points
// on the lines z = 0 and x + z = 1.5 see the light along an edge-on
// polygon's plane. The eye, too, lies in a polygon's plane (the box's face
// x = 0.5), so its depth counts cannot be decided. Stresses: the tie rule
// "a polygon edge-on to a light casts no shadow from it", silhouettes next
// to edge-on faces, an eye in the plane of a face.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0.5, 5, -7> look_at <0, 0.6, 0.5> angle 52 right x*4/3 }

light_source { <0, 1.5, 0> color rgb <0.70, 0.62, 0.50> }
// (far enough that the plane through it across its direction misses the
// scene, so that it gets shadow volumes)
light_source { <-20, 20, 0> color rgb <0.25, 0.30, 0.40> parallel point_at <0, 0, 0> }
light_source { <3, 8, -6> color rgb <0.35, 0.35, 0.35> }

background { color rgb <0.08, 0.09, 0.12> }
// The floor is a polygon, not a plane: floor points lie inside the grid, so
// the shadow volume methods count there instead of firing shadow rays.
polygon { 5, <-8, 0, -5>, <8, 0, -5>, <8, 0, 9>, <-8, 0, 9>, <-8, 0, -5> pigment { color rgb <0.78, 0.76, 0.72> } }

// The shelf, in the light's plane y = 1.5, on a post (stopping just under
// it: coplanar faces would z-fight).
polygon { 5, <1, 1.5, -1>, <3, 1.5, -1>, <3, 1.5, 1>, <1, 1.5, 1>, <1, 1.5, -1>
  pigment { color rgb <0.75, 0.35, 0.20> } }
box { <1.9, 0, 0.5>, <2.1, 1.49, 0.7> pigment { color rgb 0.5 } }
// A box whose top face lies in the light's plane.
box { <-1, 0, 1.5>, <0.5, 1.5, 2.5> pigment { color rgb <0.25, 0.50, 0.80> } }
// A card standing in the plane z = 0, edge-on to the point and the parallel light.
polygon { 5, <-3.5, 0.25, 0>, <-1.5, 0.25, 0>, <-1.5, 1.25, 0>, <-3.5, 1.25, 0>, <-3.5, 0.25, 0>
  pigment { color rgb <0.90, 0.85, 0.30> } }
// A folded card: a vertical half in the plane z = 0 (edge-on) and a half
// sloping down from the fold to the floor on the camera's side.
mesh {
  triangle { <1.5, 0, 0>, <3.5, 0, 0>, <3.5, 0.75, 0> }
  triangle { <1.5, 0, 0>, <3.5, 0.75, 0>, <1.5, 0.75, 0> }
  triangle { <1.5, 0.75, 0>, <3.5, 0.75, 0>, <3.5, 0, -0.75> }
  triangle { <1.5, 0.75, 0>, <3.5, 0, -0.75>, <1.5, 0, -0.75> }
  pigment { color rgb <0.30, 0.70, 0.35> }
}
// A triangle in the oblique plane x + y + z = 1.5 through the light.
triangle { <-1.5, 0.5, 2.5>, <-0.5, 1.5, 0.5>, <-2.5, 1.5, 2.5> pigment { color rgb <0.80, 0.45, 0.80> } }
// Ordinary occluders for contrast.
box { <-0.25, 0, -0.25>, <0.25, 0.5, 0.25> pigment { color rgb <0.85, 0.85, 0.85> } translate <-1, 0, -1.5> }
