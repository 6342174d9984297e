// water.pov -- a harbour as a city or landscape exporter (a GIS or city
// model to POV-Ray converter) writes one, in its layout: the export's
// statistics in comments, declared textures, the water as a mesh2 grid of
// the terrain's tiles at sea level with a bump-mapped texture (normal {
// ripples } with a turbulence, finish with reflection), the quay as a mesh2
// of its own with normal { bump_map { jpeg ... } } (the stone picture
// scenes/textures/stone.jpg, made by scenes/textures/make-textures.sh, as
// the exporter ships its pictures beside the scene), the buildings as
// mesh prisms (walls and flat roofs, one mesh per building), a jetty of
// polygons on box piles standing in the water, a boat hull as a mesh
// floating on it, then the camera, two point lights and the sky. The
// buildings, the jetty and the boat cast shadows on the water and the
// quay; the water reflects them through its rippled normals. It exercises
// normal { } patterns (ripples, bump_map) at +Q8 and above, reflection
// through perturbed normals, and shadows on bump-mapped surfaces (the
// shadow decisions use the geometry, the shading the perturbed normal).
// The picture is named relative to this scene's folder; POV-Ray needs
// this folder as a library path from elsewhere:
//   povray +Iscenes/water.pov +Lscenes
// (reference/make-references.sh gives it).
// Written for 4:3 images (320x240, 640x480).
//==================================================
// Export statistics:
//   water tiles............ 14 x 10 (280 triangles)
//   quay................... 1 (10 triangles)
//   buildings.............. 4 (48 triangles)
//   jetty.................. 1 deck polygon, 6 box piles
//   boat................... 1 (24 triangles)
//   in all................. 362 triangles, 1 polygon, 6 boxes
//==================================================
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
//==================================================
// Textures
//==================================================
#declare Water_tex = texture {
  pigment { color rgb <0.06, 0.20, 0.28> }
  normal { ripples 0.35 frequency 2.5 turbulence 0.3 scale 1.7 translate <0.4, 0, 1.3> }
  finish { ambient 0.05 diffuse 0.55 specular 0.5 roughness 0.02 reflection 0.3 }
}
#declare Quay_tex = texture {
  pigment { color rgb <0.62, 0.60, 0.55> }
  normal { bump_map { jpeg "textures/stone.jpg" interpolate 2 } bump_size 0.25 rotate x*90 scale 0.8 }
  finish { ambient 0.1 diffuse 0.7 }
}
#declare Wall_tex_1 = texture { pigment { color rgb <0.78, 0.52, 0.38> } finish { ambient 0.1 diffuse 0.7 } }
#declare Wall_tex_2 = texture { pigment { color rgb <0.85, 0.82, 0.70> } finish { ambient 0.1 diffuse 0.7 } }
#declare Wall_tex_3 = texture { pigment { color rgb <0.55, 0.60, 0.68> } finish { ambient 0.1 diffuse 0.7 } }
#declare Roof_tex = texture { pigment { color rgb <0.35, 0.22, 0.18> } finish { ambient 0.1 diffuse 0.6 } }
#declare Wood_tex = texture {
  pigment { color rgb <0.50, 0.36, 0.22> }
  normal { bumps 0.1 scale <0.6, 0.05, 0.05> }
  finish { ambient 0.1 diffuse 0.7 }
}
#declare Hull_tex = texture { pigment { color rgb <0.80, 0.15, 0.10> } finish { ambient 0.1 diffuse 0.6 phong 0.4 } }
//==================================================
// Water: the terrain's tiles at sea level
//==================================================
#declare NX = 14;
#declare NZ = 10;
#declare X0 = -7.3;
#declare X1 = 6.9;
#declare Z0 = -4.1;
#declare Z1 = 2.05;
mesh2 {
  vertex_vectors { (NX + 1)*(NZ + 1),
    #declare I = 0; #while (I <= NZ) #declare J = 0; #while (J <= NX)
      <X0 + (X1 - X0)*J/NX, 0, Z0 + (Z1 - Z0)*I/NZ>,
    #declare J = J + 1; #end #declare I = I + 1; #end
  }
  face_indices { 2*NX*NZ,
    #declare I = 0; #while (I < NZ) #declare J = 0; #while (J < NX)
      #declare A = I*(NX + 1) + J;
      <A, A + 1, A + NX + 2>, <A, A + NX + 2, A + NX + 1>,
    #declare J = J + 1; #end #declare I = I + 1; #end
  }
  texture { Water_tex }
}
//==================================================
// Quay: a stone bank behind the water, its front wall and top
//==================================================
mesh2 {
  vertex_vectors { 8,
    <-7.3, -0.2, 2.05>, <6.9, -0.2, 2.05>, <6.9, 0.45, 2.05>, <-7.3, 0.45, 2.05>,
    <-7.3, 0.45, 9.3>, <6.9, 0.45, 9.3>, <6.9, -0.2, 9.3>, <-7.3, -0.2, 9.3>,
  }
  face_indices { 10,
    <0, 1, 2>, <0, 2, 3>, <3, 2, 5>, <3, 5, 4>,
    <1, 6, 5>, <1, 5, 2>, <7, 0, 3>, <7, 3, 4>, <6, 7, 4>, <6, 4, 5>,
  }
  texture { Quay_tex }
}
//==================================================
// Buildings: footprint prisms, walls and a flat roof
//==================================================
// Building(X, Z, W, D, H, angle, texture): a W by D footprint centred at
// <X, 0.45, Z>, H high, turned by angle about y.
#macro Building(BX, BZ, BW, BD, BH, BA, BT)
mesh {
  #local P0 = <-BW/2, 0, -BD/2>; #local P1 = <BW/2, 0, -BD/2>;
  #local P2 = <BW/2, 0, BD/2>;   #local P3 = <-BW/2, 0, BD/2>;
  #local U = <0, BH, 0>;
  triangle { P0, P1, P1 + U } triangle { P0, P1 + U, P0 + U }
  triangle { P1, P2, P2 + U } triangle { P1, P2 + U, P1 + U }
  triangle { P2, P3, P3 + U } triangle { P2, P3 + U, P2 + U }
  triangle { P3, P0, P0 + U } triangle { P3, P0 + U, P3 + U }
  triangle { P0 + U, P1 + U, P2 + U texture { Roof_tex } }
  triangle { P0 + U, P2 + U, P3 + U texture { Roof_tex } }
  triangle { P0, P1, P2 } triangle { P0, P2, P3 }
  texture { BT }
  rotate y*BA translate <BX, 0.45, BZ>
}
#end
Building(-4.6, 3.6, 2.1, 1.6, 1.6, 8, Wall_tex_1)
Building(-1.9, 4.3, 1.7, 1.8, 2.2, -5, Wall_tex_2)
Building(1.2, 3.4, 2.4, 1.4, 1.3, 12, Wall_tex_3)
Building(4.3, 4.1, 1.6, 2.0, 1.9, -9, Wall_tex_1)
//==================================================
// Jetty: a deck polygon on piles, out over the water
//==================================================
polygon { 5, <-0.42, 0>, <0.42, 0>, <0.42, 3.1>, <-0.42, 3.1>, <-0.42, 0>
  texture { Wood_tex }
  rotate x*90 rotate y*-14 translate <2.45, 0.38, -1.05>
}
#declare Pile = box { <-0.06, -0.3, -0.06>, <0.06, 0.38, 0.06> texture { Wood_tex } }
#declare K = 0;
#while (K < 3)
  object { Pile translate <-0.33, 0, 0.25 + 1.2*K> rotate y*-14 translate <2.45, 0, -1.05> }
  object { Pile translate <0.33, 0, 0.25 + 1.2*K> rotate y*-14 translate <2.45, 0, -1.05> }
  #declare K = K + 1;
#end
//==================================================
// Boat: an open hull floating on the water
//==================================================
mesh {
  #declare S0 = <-0.95, 0.32, 0>;  #declare S1 = <0.95, 0.32, 0>;   // bow, stern at the rail
  #declare B0 = <-0.75, -0.08, 0>; #declare B1 = <0.70, -0.08, 0>;  // keel ends
  #declare Q = 0;
  #while (Q < 2)
    #declare F = 1 - 2*Q;   // the two sides
    #declare R0 = <-0.45, 0.32, 0.42*F>; #declare R1 = <0.55, 0.32, 0.40*F>;
    #declare K0 = <-0.40, -0.05, 0.18*F>; #declare K1 = <0.50, -0.05, 0.17*F>;
    triangle { S0, R0, K0 } triangle { S0, K0, B0 }
    triangle { R0, R1, K1 } triangle { R0, K1, K0 }
    triangle { R1, S1, B1 } triangle { R1, B1, K1 }
    triangle { B0, K0, <-0.40, -0.08, 0> } triangle { K0, K1, <0.50, -0.08, 0> }
    triangle { K0, <0.50, -0.08, 0>, <-0.40, -0.08, 0> } triangle { K1, B1, <0.50, -0.08, 0> }
    triangle { S0, R0, <-0.40, 0.20, 0> } triangle { R1, S1, <0.50, 0.20, 0> }
    #declare Q = Q + 1;
  #end
  texture { Hull_tex }
  rotate y*23 translate <-1.32, 0, -1.87>
}
//==================================================
// Camera
//==================================================
camera {
  perspective
  up y
  right x*image_width/image_height
  location <-0.6, 4.4, -9.2>
  look_at <0.2, 0.8, 1.4>
  angle 50
}
//==================================================
// Lights
//==================================================
light_source { <-6.5, 9.5, -3.0> color rgb <0.95, 0.90, 0.80> }
light_source { <7.0, 6.5, -5.5> color rgb <0.25, 0.30, 0.40> }
//==================================================
// Sky
//==================================================
background { color rgb <0.55, 0.68, 0.85> }
