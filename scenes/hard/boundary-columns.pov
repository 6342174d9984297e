// boundary-columns.pov -- hard case 3: shadow boundaries that fall exactly
// on a column (and a row) of pixel centres.
// An orthographic camera looks straight down at the floor. At 320x240 its
// view is 8 x 6 units and it is offset by half a pixel, so the centre of
// pixel column i lies at x = i/40 - 4 and that of row j at z = 3 - j/40:
// columns 120, 160, 200 and 240 at x = -1, 0, 1, 2, rows 80 and 120 at
// z = 1 and 0 (up to the rounding of POV-Ray's pixel arithmetic). Each
// occluder edge lies in a plane that holds its light and one of those
// columns (or rows) of pixel centres, so the shadow boundary on the floor
// runs through the pixel centres themselves and each pixel on it is decided
// by a tie. Stresses: ties between lit and shadowed along whole columns,
// for point lights (overhead and off to the side) and a parallel light.
#version 3.7;
global_settings { assumed_gamma 1 }

camera {
  orthographic
  location <-0.0125, 5, 0.0125>
  direction -y
  right x*8
  up z*6
}

// Overhead: in the planes x = 0 and z = 0 (columns 160 and row 120).
light_source { <0, 4, 0> color rgb <0.55, 0.52, 0.48> }
// In the plane x = 2 (column 240), off to the side in z.
light_source { <2, 3, -2.5> color rgb <0.30, 0.34, 0.42> }
// Parallel, direction (0, -2, 1): its shadow boundaries of edges running
// along z at x = -1 lie in the plane x = -1 (column 120).
light_source { <-3, 6, -3> color rgb <0.25, 0.22, 0.18> parallel point_at <-3, 4, -2> }

background { color rgb <0.1, 0.1, 0.12> }
plane { y, 0 pigment { color rgb <0.8, 0.78, 0.74> } }

// A horizontal card whose corner sits under the overhead light: its edges
// on x = 0 and z = 0 cast boundaries on column 160 and row 120.
polygon { 5, <0, 1, 0>, <1, 1, 0>, <1, 1, 1>, <0, 1, 1>, <0, 1, 0>
  pigment { color rgb <0.8, 0.3, 0.2> } }
// A box whose edge runs along the line x = 0, z = 0 under the light: two of
// its faces are edge-on to the overhead light (the light in their planes).
box { <-1.5, 0, -1.5>, <0, 0.5, 0> pigment { color rgb <0.2, 0.5, 0.8> } }
// A vertical card in the plane x = 2 (edge-on to the second light) and a
// horizontal one with an edge on x = 2: its shadow boundary falls on
// column 240.
polygon { 5, <2, 0.2, 0.5>, <2, 0.2, 1.5>, <2, 1.2, 1.5>, <2, 1.2, 0.5>, <2, 0.2, 0.5>
  pigment { color rgb <0.3, 0.7, 0.3> } }
polygon { 5, <2, 1.5, -1.6>, <3.2, 1.5, -1.6>, <3.2, 1.5, -0.8>, <2, 1.5, -0.8>, <2, 1.5, -1.6>
  pigment { color rgb <0.9, 0.8, 0.3> } }
// Triangles with an edge along z at x = -1: the parallel light's boundary
// falls on column 120. Its other edge runs diagonally.
triangle { <-1, 1, 0.5>, <-1, 1, 2.0>, <-2.2, 1, 2.0> pigment { color rgb <0.7, 0.4, 0.8> } }
// A card standing on the floor in the plane z = 1: the camera sees it
// exactly edge-on, along row 80 of pixel centres.
polygon { 5, <-3.5, 0, 1>, <-2, 0, 1>, <-2, 0.8, 1>, <-3.5, 0.8, 1>, <-3.5, 0, 1>
  pigment { color rgb <0.9, 0.9, 0.9> } }
