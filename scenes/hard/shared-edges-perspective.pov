// shared-edges-perspective.pov -- hard case 2 again (see shared-edges.pov):
// the same welded canopy of 1428 triangles with holes, the same T-junction
// block and the same two lights at exact positions, seen by a perspective
// camera in front of the canopy and below it. Shadow rays no longer pass
// exactly through shared edges at pixel centres, but the eye has a known
// depth count, so the shadow volume methods count crossings of the
// canopy's 246 silhouette shadow polygons per light (its other 2030 edges
// are shared by faces that continue each other and cancel) from the eye
// and from pixel to pixel. Stresses: counting through a welded mesh,
// T-junction edges that do not cancel (their shadow polygons overlap with
// opposite signs), the canopy's own polygons seen from their shadow side.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <-0.2, 0.9, -3.4> look_at <-0.2, 0, -0.4> angle 80 right x*4/3 }

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
