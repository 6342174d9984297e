// tree.pov -- a tree as the Arbaro tree generator writes one, in its
// layout: the species, seed and statistics in comments, the stems level
// by level (the trunk as a mesh2 of rings, the branches as a mesh of
// tapered segments), the leaves as one mesh2 of quads with uv_vectors,
// the textures declared before the tree, and the scene that places it:
// object { TREE_stems } and object { TREE_leaves } in a union, on a ground,
// under a sun and a fill light, then the camera. Arbaro writes the geometry
// as literal data; here the same data are computed by #while loops in the
// mesh2 and mesh blocks, the leaves' places and turns drawn with seed()
// and rand() as Arbaro draws them from its seed. It exercises texture_map
// (the bark: a gradient with turbulence between two bark textures; the
// leaves: a bozo between two leaf textures, one of them with a specular
// highlight),
// many small triangles casting shadows on the ground, on the trunk and on
// each other, and a uv-mapped mesh2.
// Written for 4:3 images (320x240, 640x480).
//==================================================
// Arbaro tree: species "aspen_like", seed 13
//   stems level 0 (trunk)...... 1 (160 triangles)
//   stems level 1 (branches)... 7 (168 triangles)
//   leaves..................... 310 (620 triangles)
//   in all..................... 948 triangles
//==================================================
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
//==================================================
// Textures
//==================================================
#declare Bark_tex_1 = texture { pigment { color rgb <0.36, 0.27, 0.20> } finish { ambient 0.1 diffuse 0.7 } }
#declare Bark_tex_2 = texture { pigment { color rgb <0.62, 0.58, 0.50> } finish { ambient 0.1 diffuse 0.6 } }
#declare Stem_tex = texture {
  gradient y
  texture_map { [0 Bark_tex_1] [0.45 Bark_tex_2] [1 Bark_tex_1] }
  turbulence 0.4
  scale 0.23
}
#declare Leaf_tex_1 = texture { pigment { color rgb <0.22, 0.48, 0.12> } finish { ambient 0.1 diffuse 0.7 } }
#declare Leaf_tex_2 = texture {
  pigment { color rgb <0.55, 0.62, 0.16> }
  finish { ambient 0.1 diffuse 0.6 specular 0.2 roughness 0.05 }
}
#declare Leaf_tex = texture {
  bozo
  texture_map { [0.25 Leaf_tex_1] [0.75 Leaf_tex_2] }
  scale 0.35
}
//==================================================
// Stems, level 0: the trunk, a mesh2 of NR rings of NS vertices
//==================================================
#declare NS = 10;
#declare NR = 8;
#declare Trunk_h = 2.15;
// TrunkAt(F): the trunk's axis at the fraction F of its height (a slight bend)
#macro TrunkAt(F) <0.12*F*F, Trunk_h*F, 0.05*F> #end
#macro TrunkR(F) (0.13 - 0.09*F) #end
#declare aspen_like_13_stems_0 = mesh2 {
  vertex_vectors { (NR + 1)*NS,
    #declare I = 0; #while (I <= NR) #declare J = 0; #while (J < NS)
      #declare F = I/NR; #declare A = 2*pi*(J + 0.5*mod(I, 2))/NS;
      TrunkAt(F) + TrunkR(F)*<cos(A), 0, sin(A)>,
    #declare J = J + 1; #end #declare I = I + 1; #end
  }
  face_indices { 2*NR*NS,
    #declare I = 0; #while (I < NR) #declare J = 0; #while (J < NS)
      #declare J2 = mod(J + 1, NS);
      <I*NS + J, I*NS + J2, (I + 1)*NS + J>, <I*NS + J2, (I + 1)*NS + J2, (I + 1)*NS + J>,
    #declare J = J + 1; #end #declare I = I + 1; #end
  }
}
//==================================================
// Stems, level 1: the branches, tapered segments of 6 sides
//==================================================
#declare NB = 7;
#declare Branch_base = array[NB]
#declare Branch_dir = array[NB]
#declare Branch_len = array[NB]
#declare K = 0;
#while (K < NB)
  #declare F = 0.50 + 0.065*K;
  #declare Branch_base[K] = TrunkAt(F);
  #declare Branch_dir[K] = vrotate(vrotate(<1, 0, 0>, <0, 0, 52 - 3*K>), <0, 31 + 137.5*K, 0>);
  #declare Branch_len[K] = 1.5 - 0.1*K;
  #declare K = K + 1;
#end
// Segment(P0, P1, R0, R1): the sides of a 6-sided frustum from P0 (radius
// R0) to P1 (radius R1), as 12 triangles.
#macro Segment(P0, P1, R0, R1)
  #local D = vnormalize(P1 - P0);
  #local E1 = vnormalize(vcross(D, <0.3, 1, 0.2>));
  #local E2 = vcross(D, E1);
  #local M = 0;
  #while (M < 6)
    #local A0 = 2*pi*M/6; #local A1 = 2*pi*(M + 1)/6;
    #local C0 = cos(A0)*E1 + sin(A0)*E2; #local C1 = cos(A1)*E1 + sin(A1)*E2;
    triangle { P0 + R0*C0, P0 + R0*C1, P1 + R1*C0 }
    triangle { P0 + R0*C1, P1 + R1*C1, P1 + R1*C0 }
    #local M = M + 1;
  #end
#end
#declare aspen_like_13_stems_1 = mesh {
  #declare K = 0;
  #while (K < NB)
    #declare P0 = Branch_base[K];
    #declare P1 = P0 + 0.55*Branch_len[K]*Branch_dir[K];
    #declare P2 = P1 + 0.45*Branch_len[K]*vnormalize(Branch_dir[K] + <0, 0.35, 0>);
    Segment(P0, P1, 0.055, 0.035)
    Segment(P1, P2, 0.035, 0.012)
    #declare K = K + 1;
  #end
}
//==================================================
// Leaves: quads along the branches and at the crown, uv-mapped
//==================================================
#declare NL_branch = 40;
#declare NL_crown = 30;
#declare NL = NB*NL_branch + NL_crown;
#declare Leaf_seed = seed(13);
#declare aspen_like_13_leaves = mesh2 {
  vertex_vectors { 4*NL,
    #declare L = 0;
    #while (L < NL)
      #if (L < NB*NL_branch)
        #declare K = div(L, NL_branch);
        #declare T = 0.3 + 0.7*rand(Leaf_seed);
        #declare C = Branch_base[K] + T*Branch_len[K]*vnormalize(Branch_dir[K] + <0, 0.2*T, 0>);
      #else
        #declare C = TrunkAt(1) + <0, 0.1, 0>;
      #end
      #declare C = C + 0.5*<rand(Leaf_seed) - 0.5, rand(Leaf_seed) - 0.5, rand(Leaf_seed) - 0.5>;
      #declare Turn = <360*rand(Leaf_seed), 360*rand(Leaf_seed), 360*rand(Leaf_seed)>;
      #declare Ax = vrotate(<0.09, 0, 0>, Turn);
      #declare Ay = vrotate(<0, 0.14, 0>, Turn);
      C - Ay, C + Ax, C + Ay, C - Ax,
      #declare L = L + 1;
    #end
  }
  uv_vectors { 4, <0.5, 0>, <1, 0.5>, <0.5, 1>, <0, 0.5> }
  face_indices { 2*NL,
    #declare L = 0;
    #while (L < NL)
      <4*L, 4*L + 1, 4*L + 2>, <4*L, 4*L + 2, 4*L + 3>,
      #declare L = L + 1;
    #end
  }
  uv_indices { 2*NL,
    #declare L = 0;
    #while (L < NL)
      <0, 1, 2>, <0, 2, 3>,
      #declare L = L + 1;
    #end
  }
}
//==================================================
// The tree
//==================================================
#declare aspen_like_13 = union {
  object { aspen_like_13_stems_0 texture { Stem_tex } }
  object { aspen_like_13_stems_1 texture { Stem_tex } }
  object { aspen_like_13_leaves texture { Leaf_tex } }
}
object { aspen_like_13 rotate y*10 }
//==================================================
// Ground, lights, camera
//==================================================
plane { y, 0
  pigment { bozo color_map { [0 color rgb <0.35, 0.42, 0.20>] [1 color rgb <0.48, 0.45, 0.30>] } scale 0.6 }
  finish { ambient 0.1 diffuse 0.7 }
}
background { color rgb <0.60, 0.72, 0.88> }
light_source { <-5.5, 9.0, -4.5> color rgb <1.0, 0.95, 0.85> }
light_source { <6.0, 4.5, -7.0> color rgb <0.25, 0.28, 0.36> }
camera {
  perspective
  up y
  right x*image_width/image_height
  location <0.3, 1.3, -6.4>
  look_at <0.1, 1.55, 0>
  angle 48
}
