// grazing.pov -- hard case 7: grazing light and grazing view.
// A point light 0.02 above the floor, 8 units away, lights the floor at
// N.L of about 0.0025 (it is bright, so that this still shows) and throws
// the objects' shadows along it. A second
// light stands 0.001 in front of the plane of a wall panel (N.L ~ 1e-4 on
// the panel), and lights a faceted column (facets on both sides of the
// terminator, some within a degree of edge-on) and a smooth_triangle
// half-cylinder whose interpolated normals turn away from the light inside
// facets that face it. The camera stands 0.15 above the floor, so camera
// rays meet the floor at a few degrees and a long wall on the right almost
// edge-on. Stresses: the facing test (N.L near 0, on either side of it) as
// the self-shadow decision, shadow polygons nearly parallel to the floor,
// hit points at grazing incidence far from the eye.
#version 3.7;
global_settings { assumed_gamma 1 }

camera { location <0.2, 0.15, -6> look_at <0, 0.25, 0> angle 60 right x*4/3 }

light_source { <-8, 0.02, 2> color rgb <2.4, 2.16, 1.65> }           // almost in the floor's plane
light_source { <1.5, 2.5, 2.999> color rgb <0.35, 0.40, 0.55> }     // 0.001 before the panel's plane
light_source { <2, 9, -7> color rgb <0.12, 0.12, 0.12> }

background { color rgb <0.08, 0.09, 0.12> }

polygon { 5, <-20, 0, -8>, <20, 0, -8>, <20, 0, 30>, <-20, 0, 30>, <-20, 0, -8>
  pigment { color rgb <0.80, 0.78, 0.74> } }
// A long wall on the right, seen almost edge-on.
polygon { 5, <2.6, 0, -5>, <2.6, 0, 25>, <2.6, 2, 25>, <2.6, 2, -5>, <2.6, 0, -5>
  pigment { color rgb <0.55, 0.60, 0.70> } }
// The wall panel in the plane z = 3, facing the camera.
polygon { 5, <-3, 0, 3>, <2.4, 0, 3>, <2.4, 2.2, 3>, <-3, 2.2, 3>, <-3, 0, 3>
  pigment { color rgb <0.85, 0.80, 0.70> } }

// Blocks on the floor casting long shadows from the low light.
box { <-0.2, 0, -0.2>, <0.2, 0.4, 0.2> pigment { color rgb <0.8, 0.3, 0.2> } translate <-2.2, 0, 0.5> }
box { <-0.1, 0, -0.3>, <0.1, 0.05, 0.3> pigment { color rgb <0.3, 0.7, 0.3> } rotate y*20 translate <-1.2, 0, -1.5> }
polygon { 5, <0, 0>, <0.6, 0>, <0.6, 0.3>, <0, 0.3>, <0, 0> pigment { color rgb <0.9, 0.9, 0.4> }
  rotate y*70 translate <-0.6, 0, -3> }

// A faceted column: 24 flat facets.
#declare Segs = 24;
mesh {
  #declare i = 0;
  #while (i < Segs)
    #declare a0 = 2*pi*i/Segs; #declare a1 = 2*pi*(i+1)/Segs;
    triangle { <0.4*cos(a0), 0, 0.4*sin(a0)>, <0.4*cos(a1), 0, 0.4*sin(a1)>, <0.4*cos(a1), 1.4, 0.4*sin(a1)> }
    triangle { <0.4*cos(a0), 0, 0.4*sin(a0)>, <0.4*cos(a1), 1.4, 0.4*sin(a1)>, <0.4*cos(a0), 1.4, 0.4*sin(a0)> }
    #declare i = i + 1;
  #end
  pigment { color rgb <0.75, 0.55, 0.35> }
  translate <0.6, 0, 1.2>
}
// A smooth half-cylinder lying on its side: 8 facets, radial normals.
#declare Segs = 8;
mesh {
  #declare i = 0;
  #while (i < Segs)
    #declare a0 = pi*i/Segs; #declare a1 = pi*(i+1)/Segs;
    smooth_triangle { <-0.7, 0.5*sin(a0), 0.5*cos(a0)>, <0, sin(a0), cos(a0)>,
                      < 0.7, 0.5*sin(a0), 0.5*cos(a0)>, <0, sin(a0), cos(a0)>,
                      < 0.7, 0.5*sin(a1), 0.5*cos(a1)>, <0, sin(a1), cos(a1)> }
    smooth_triangle { <-0.7, 0.5*sin(a0), 0.5*cos(a0)>, <0, sin(a0), cos(a0)>,
                      < 0.7, 0.5*sin(a1), 0.5*cos(a1)>, <0, sin(a1), cos(a1)>,
                      <-0.7, 0.5*sin(a1), 0.5*cos(a1)>, <0, sin(a1), cos(a1)> }
    #declare i = i + 1;
  #end
  pigment { color rgb <0.40, 0.55, 0.80> }
  finish { phong 0.4 }
  rotate y*-25 translate <-1.0, 0, 1.6>
}
