// shared-edges.pov -- hard case 2: shadow rays through the shared edges and
// vertices of a welded, finely tessellated occluder, and through T-junctions.
// A canopy at y = 1 is a mesh2 grid of 32 x 24 squares of side 0.125 (two
// triangles each, every vertex shared by index), with holes: a square
// window, a checkerboard patch and a diagonal chain of squares touching only
// at their corners. Under it an orthographic camera looks straight down at
// the floor (its rays start in its own plane, y = 0.5, so the canopy above
// is not seen); at 320x240 the centre of pixel (i, j) lies on the floor at
// x = i/40 - 4, z = 3 - j/40 (up to the rounding of the pixel arithmetic).
// The light at <0, 2, 0> maps a floor point P to the canopy point P/2, so
// every 10th column and row of pixels sees it exactly through a grid line
// and every 10th diagonal through the squares' diagonals; the light at
// <0.5, 1.5, -0.25> maps P to (P + 2L)/3: a line every 15 pixels. Where
// they cross, the shadow ray passes through a vertex shared by six
// triangles. A 4 x 4 block of the grid is left out and filled by a separate
// mesh with T-junctions: the block's border vertices of the canopy lie on
// the long edges of its triangles, and inside it one half is a single
// square while the other is split in two, so its middle vertex lies on the
// first half's edge. All vertices and light positions are multiples of
// 0.125, exact in binary. Stresses: watertight shadow rays (no light
// leaking through shared edges or vertices), silhouette edges cancelling
// between welded faces, T-junctions whose edges are not shared and so do
// not cancel. POV-Ray's ray/triangle test lets light through these shared
// edges (lines of lit pixels every 10 and 15 columns and rows); hstrace's
// is watertight, so the regression test counts those pixels as POV-Ray's:
// hstrace-regress: povray-leaks
#version 3.7;
global_settings { assumed_gamma 1 }

camera {
  orthographic
  location <-0.0125, 0.5, 0.0125>
  direction -y
  right x*8
  up z*6
}

light_source { <0, 2, 0> color rgb <0.75, 0.70, 0.60> }
light_source { <0.5, 1.5, -0.25> color rgb <0.25, 0.35, 0.55> }

background { color rgb <0.1, 0.1, 0.12> }
// The floor is a polygon (not a plane) so that it lies inside the grid and
// the shadow volume methods count along it from pixel to pixel.
polygon { 5, <-4.5, 0, -3.5>, <4.5, 0, -3.5>, <4.5, 0, 3.5>, <-4.5, 0, 3.5>, <-4.5, 0, -3.5>
  pigment { color rgb <0.85, 0.85, 0.85> } }

#declare S = 0.125;
#declare NX = 32;   // squares along x, from x = -2
#declare NZ = 24;   // squares along z, from z = -1.5
// Holes (squares (i, j), i along x, j along z):
//   the T-junction block  4 <= i <= 7,   4 <= j <= 7  (filled below)
//   a square window       22 <= i <= 25, 14 <= j <= 17
//   a checkerboard        8 <= i <= 15,  16 <= j <= 19, where i + j is even
//   a diagonal chain      i = 18 + k, j = 3 + k, k = 0 .. 5
// 768 - 16 - 16 - 16 - 6 = 714 squares remain: 1428 triangles.
mesh2 {
  vertex_vectors { (NX + 1)*(NZ + 1),
    #declare j = 0; #while (j <= NZ) #declare i = 0; #while (i <= NX)
      <-2 + i*S, 1, -1.5 + j*S>,
    #declare i = i + 1; #end #declare j = j + 1; #end
  }
  face_indices { 1428,
    #declare j = 0; #while (j < NZ)
      #declare Even = 1 - 2*(j/2 - floor(j/2));
      #declare i = 0; #while (i < NX)
        #declare Hole = 0;
        #if (i >= 4 & i <= 7 & j >= 4 & j <= 7) #declare Hole = 1; #end
        #if (i >= 22 & i <= 25 & j >= 14 & j <= 17) #declare Hole = 1; #end
        #if (i >= 8 & i <= 15 & j >= 16 & j <= 19 & Even) #declare Hole = 1; #end
        #if (i - j = 15 & i >= 18 & i <= 23) #declare Hole = 1; #end
        #if (!Hole)
          #declare a = j*(NX + 1) + i;
          <a, a + 1, a + NX + 2>, <a, a + NX + 2, a + NX + 1>,
        #end
        #declare Even = 1 - Even;
      #declare i = i + 1; #end
    #declare j = j + 1; #end
  }
  pigment { color rgb <0.6, 0.3, 0.2> }
}

// The T-junction block: x in [-1.5, -1], z in [-1, -0.5]. Its left half is
// one square (two triangles); its right half is two squares, whose shared
// corner <-1.25, 1, -0.75> lies on the left half's edge.
mesh {
  triangle { <-1.5, 1, -1>,    <-1.25, 1, -1>,    <-1.25, 1, -0.5> }
  triangle { <-1.5, 1, -1>,    <-1.25, 1, -0.5>,  <-1.5, 1, -0.5> }
  triangle { <-1.25, 1, -1>,   <-1, 1, -1>,       <-1, 1, -0.75> }
  triangle { <-1.25, 1, -1>,   <-1, 1, -0.75>,    <-1.25, 1, -0.75> }
  triangle { <-1.25, 1, -0.75>, <-1, 1, -0.75>,   <-1, 1, -0.5> }
  triangle { <-1.25, 1, -0.75>, <-1, 1, -0.5>,    <-1.25, 1, -0.5> }
  pigment { color rgb <0.2, 0.4, 0.6> }
}
