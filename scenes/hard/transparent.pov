// transparent.pov -- hard case 10: transparent occluders in front of opaque
// ones.
// Shadow rays from the floor pass first through filtering (rgbf) and
// transmitting (rgbt) cards and then reach, or miss, opaque blocks behind
// them: the light that arrives is filtered, blocked, or both. Three cards
// of different colours overlap, so their shadows multiply; a transparent
// box (two faces on every shadow ray through it) stands in front of an
// opaque post, one with an interior of ior 1.5 bends the camera's rays; an
// opaque card is glued edge to edge to a transparent one. Camera rays
// pass through the cards too, so transmitted rays reach shadowed points.
// Stresses: the transparent depth count beside the opaque one, filtered
// light taken by the shadow ray only, decisions at points reached through
// transparent surfaces.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }

camera { location <0.3, 3.2, -6.2> look_at <0, 0.7, 0.4> angle 52 right x*4/3 }

light_source { <-2.5, 5.5, -3.5> color rgb <0.75, 0.72, 0.65> }
light_source { <3.5, 3, -1> color rgb <0.30, 0.34, 0.45> }

background { color rgb <0.08, 0.09, 0.12> }
polygon { 5, <-7, 0, -6>, <7, 0, -6>, <7, 0, 8>, <-7, 0, 8>, <-7, 0, -6>
  pigment { color rgb <0.80, 0.78, 0.74> } }
polygon { 5, <-7, 0, 3>, <7, 0, 3>, <7, 4, 3>, <-7, 4, 3>, <-7, 0, 3>
  pigment { color rgb <0.70, 0.72, 0.75> } }

// Three overlapping cards: filter, transmit, filter+transmit.
polygon { 5, <-0.6, 0, 0>, <0.6, 0, 0>, <0.6, 1, 0>, <-0.6, 1, 0>, <-0.6, 0, 0>
  pigment { color rgbf <0.95, 0.25, 0.20, 0.8> } translate <-2.0, 0.4, 0.0> }
polygon { 5, <-0.6, 0, 0>, <0.6, 0, 0>, <0.6, 1, 0>, <-0.6, 1, 0>, <-0.6, 0, 0>
  pigment { color rgbt <0.20, 0.85, 0.30, 0.6> } rotate y*15 translate <-1.6, 0.5, 0.35> }
polygon { 5, <-0.6, 0, 0>, <0.6, 0, 0>, <0.6, 1, 0>, <-0.6, 1, 0>, <-0.6, 0, 0>
  pigment { color rgbft <0.25, 0.35, 0.95, 0.5, 0.3> } rotate y*-10 translate <-2.3, 0.6, 0.7> }
// An opaque block behind them (from the main light).
box { <-0.3, 0, -0.3>, <0.3, 0.7, 0.3> pigment { color rgb <0.85, 0.65, 0.25> } translate <-1.6, 0, 1.4> }

// A filtering box in front of an opaque post. The transparent boxes stand
// 0.02 above the floor: a bottom face in the floor's plane, seen through
// the box, would z-fight with the floor.
box { <-0.4, 0.02, -0.4>, <0.4, 0.9, 0.4> pigment { color rgbf <0.6, 0.9, 0.95, 0.85> } translate <0.3, 0, -0.4> }
box { <-0.12, 0, -0.12>, <0.12, 1.4, 0.12> pigment { color rgb <0.25, 0.35, 0.75> } translate <0.8, 0, 0.6> }
// A glass slab (ior 1.5) bending the camera's rays, over an opaque card.
box { <-0.6, 0.02, -0.05>, <0.6, 0.8, 0.05> pigment { color rgbf <1, 1, 1, 0.9> } interior { ior 1.5 }
  rotate y*-25 translate <1.9, 0, -1.2> }
polygon { 4, <0, 0, 0>, <0.6, 0, 0.3>, <0.3, 0, -0.4>, <0, 0, 0> pigment { color rgb <0.7, 0.2, 0.6> }
  translate <1.8, 0.001, -0.7> }

// An opaque card glued edge to edge to a transmitting one, raised on a post.
union {
  polygon { 5, <-0.8, 0, 0>, <0, 0, 0>, <0, 0, 0.8>, <-0.8, 0, 0.8>, <-0.8, 0, 0> pigment { color rgb <0.9, 0.9, 0.9> } }
  polygon { 5, <0, 0, 0>, <0.8, 0, 0>, <0.8, 0, 0.8>, <0, 0, 0.8>, <0, 0, 0> pigment { color rgbt <0.9, 0.6, 0.3, 0.7> } }
  box { <-0.05, -1.1, 0.35>, <0.05, 0, 0.45> pigment { color rgb 0.4 } }
  rotate z*10 translate <2.2, 1.1, 1.3>
}
