// marbles.pov -- hstrace's curved-object benchmark (issue 43, bench/shapes.sh):
// a board of 400 marbles (spheres: opaque, glossy and glass), rings (tori),
// posts (cylinders) capped by cones, and CSG pieces (lenses made by
// intersection, beads bored by difference, merged glass clusters), on a
// table under three point lights. Every shadow is a hard shadow; the glass
// filters the light that passes it.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

// Set to 0 to leave the CSG pieces out.
#ifndef (With_CSG) #declare With_CSG = 1; #end

camera { location <0, 11, -15> look_at <0, 0, 0.6> angle 52 }
light_source { <-9, 16, -8> color rgb <0.75, 0.72, 0.66> }
light_source { <10, 12, -4> color rgb <0.35, 0.38, 0.46> }
light_source { <2, 9, 12> color rgb <0.28, 0.27, 0.24> }
background { color rgb <0.05, 0.05, 0.07> }

plane { y, 0 pigment { checker color rgb <0.55, 0.52, 0.47> color rgb <0.32, 0.30, 0.28> scale 1.5 }
        finish { diffuse 0.8 ambient 0.05 } }

#declare Opaque = finish { diffuse 0.75 specular 0.3 roughness 0.02 ambient 0.05 }
#declare Glossy = finish { diffuse 0.6 specular 0.6 roughness 0.005 reflection 0.15 ambient 0.05 }
#declare Glass = finish { diffuse 0.1 specular 0.8 roughness 0.003 reflection 0.05 ambient 0.0 }

// 20 x 20 marbles, three kinds in turn
#declare I = 0;
#while (I < 20)
  #declare J = 0;
  #while (J < 20)
    #declare X = -9.5 + I;
    #declare Z = -7 + J * 0.8;
    #declare K = mod(I * 7 + J * 3, 5);
    #declare R = 0.22 + 0.06 * mod(I + J, 3);
    sphere { <X, R, Z>, R
      #if (K < 2)
        pigment { color rgb <0.2 + 0.04 * I, 0.25 + 0.03 * J, 0.7 - 0.02 * I> } finish { Opaque }
      #else
        #if (K < 4)
          pigment { color rgb <0.8 - 0.03 * J, 0.3 + 0.02 * I, 0.2> } finish { Glossy }
        #else
          pigment { color rgbf <0.7, 0.9, 0.8, 0.85> } finish { Glass }
          interior { ior 1.5 }
        #end
      #end
    }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end

// posts with cone caps, and rings lying around their feet
#declare P = 0;
#while (P < 12)
  #declare A = P * 30;
  #declare C = <9.8 * cos(radians(A)), 0, 8.4 * sin(radians(A)) + 1.2>;
  cylinder { C, C + <0, 2.4, 0>, 0.18 pigment { color rgb <0.75, 0.7, 0.6> } finish { Opaque } }
  cone { C + <0, 2.4, 0>, 0.32, C + <0, 3.0, 0>, 0.0 pigment { color rgb <0.8, 0.25, 0.2> } finish { Glossy } }
  torus { 0.5, 0.08 translate C + <0, 0.08, 0> pigment { color rgb <0.85, 0.7, 0.25> } finish { Glossy } }
  #declare P = P + 1;
#end

#if (With_CSG)
  // lenses: two spheres' common part, tilted
  #declare L = 0;
  #while (L < 10)
    intersection {
      sphere { <0, 0, -0.35>, 0.6 }
      sphere { <0, 0, 0.35>, 0.6 }
      rotate <70, L * 36, 0>
      translate <-9 + L * 2, 0.35, -8.6>
      pigment { color rgbf <0.9, 0.85, 0.6, 0.7> } finish { Glass } interior { ior 1.4 }
    }
    #declare L = L + 1;
  #end
  // beads: spheres bored through by cylinders
  #declare B = 0;
  #while (B < 10)
    difference {
      sphere { 0, 0.4 }
      cylinder { <0, -0.5, 0>, <0, 0.5, 0>, 0.15 }
      rotate <90, 0, B * 18>
      translate <-9 + B * 2, 0.4, 8.4>
      pigment { color rgb <0.3, 0.6, 0.35> } finish { Glossy }
    }
    #declare B = B + 1;
  #end
  // glass clusters: three spheres merged, no surfaces inside
  #declare G = 0;
  #while (G < 6)
    merge {
      sphere { <-0.25, 0.3, 0>, 0.3 }
      sphere { <0.25, 0.3, 0>, 0.3 }
      sphere { <0, 0.7, 0>, 0.3 }
      translate <-7.5 + G * 3, 0, 10>
      pigment { color rgbf <0.6, 0.8, 1.0, 0.9> } finish { Glass } interior { ior 1.33 }
    }
    #declare G = G + 1;
  #end
#end
