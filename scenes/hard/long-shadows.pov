// long-shadows.pov -- hard case 8: long shadows on an infinite plane.
// A point light 0.9 above the ground and a parallel light about 5 degrees
// above the horizon throw the shadows of a few posts, a card and a low
// platform far beyond the objects along an infinite plane, out to the
// horizon; posts taller than the point light cast shadows that never end.
// The plane is outside the grid, so its points are decided by shadow rays
// that cross the whole grid, while the platform's top (inside the grid) is
// counted. Stresses: shadow polygons extruded nearly horizontally and to
// infinity, receivers far outside the grid box, shadow boundaries
// converging at the horizon (sub-pixel slivers).
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <-3.2, 2.2, -4.5> look_at <1.5, 0.2, 3> angle 58 right x*4/3 }

light_source { <-4.5, 0.9, -1.25> color rgb <0.75, 0.68, 0.55> }
light_source { <-10, 1, 4> color rgb <0.30, 0.35, 0.50> parallel point_at <0, 0, 0> }
light_source { <0, 12, -6> color rgb <0.15, 0.15, 0.15> }

background { color rgb <0.10, 0.12, 0.18> }
plane { y, 0 pigment { color rgb <0.78, 0.76, 0.72> } }

// A low platform.
box { <-2, 0, -1.5>, <1, 0.1, 1.5> pigment { color rgb <0.55, 0.55, 0.6> } }
// Posts: two taller than the point light, one shorter.
#declare Post = box { <-0.08, 0, -0.08>, <0.08, 1, 0.08> }
object { Post scale <1, 1.4, 1> pigment { color rgb <0.8, 0.3, 0.2> } translate <-1.5, 0.1, -0.9> }
object { Post scale <1, 0.6, 1> pigment { color rgb <0.2, 0.6, 0.3> } translate <-1.2, 0.1, 0.4> }
object { Post scale <1, 1.1, 1> pigment { color rgb <0.3, 0.4, 0.8> } rotate y*20 translate <0.2, 0, 2.2> }
// A card standing on the platform, facing the point light.
polygon { 5, <0, 0>, <0.8, 0>, <0.8, 0.5>, <0, 0.5>, <0, 0> pigment { color rgb <0.9, 0.85, 0.4> }
  rotate y*75 translate <-0.4, 0.1, -0.5> }
// A triangle leaning over the plane beyond the platform.
triangle { <0, 0, 0>, <0.7, 0, 0>, <0.35, 0.6, 0.25> pigment { color rgb <0.7, 0.4, 0.8> } translate <1.6, 0, -0.6> }
