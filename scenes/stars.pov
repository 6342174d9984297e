// stars.pov -- star-shaped polyhedra on a floor, after the "Stars" scene of
// Eo, Choi and Kyung. Written for hstrace: polygons only (meshes of
// triangles). Three kinds of star: spiked balls (a faceted sphere with a
// four-sided pyramid raised on every facet), stellated octahedra (two
// interpenetrating tetrahedra: a three-sided spike on each face of an
// octahedron) and thick five-pointed stars (a pentagram rim between two
// apexes). Five lights at moderate distance throw overlapping shadows of
// the spikes across the floor. About 4,200 polygons. Written for 4:3 images.
#version 3.7;
global_settings { assumed_gamma 1 }

camera {
  location <0.4, 6.6, -9.4>
  look_at  <0.2, 0.3, 0.7>
  angle 50
  right x*4/3
}

light_source { <-4.5, 6.5, -4.0> color rgb <0.55, 0.52, 0.46> }
light_source { < 5.0, 5.0, -3.0> color rgb <0.34, 0.36, 0.44> }
light_source { < 0.5, 4.0,  5.5> color rgb <0.30, 0.26, 0.22> }
light_source { <-6.0, 3.0,  2.0> color rgb <0.18, 0.22, 0.30> }
light_source { < 3.0, 7.5,  1.0> color rgb <0.22, 0.22, 0.20> }

background { color rgb <0.04, 0.05, 0.08> }

// ---- the floor: a polygon (inside the grid, so its shadows are counted) ----
polygon { 5, <-9, 0, -7>, <9, 0, -7>, <9, 0, 9>, <-9, 0, 9>, <-9, 0, -7>
  pigment { color rgb <0.66, 0.64, 0.60> } finish { phong 0.15 phong_size 20 } }

// ---- spiked balls ---------------------------------------------------------
// A sphere of radius 1 cut into NL bands of latitude and NM of longitude;
// on every facet a pyramid whose apex lies at radius Spike on the facet's
// middle direction (three sides at the poles, where a facet is a triangle).
#declare NL = 9;
#declare NM = 16;
#declare Spike = 1.9;
#declare NBall = 7;
#declare B = 0;
#while (B < NBall)
  #if (B = 0)     #declare At = <-2.6, 0, 1.2>;  #declare Sc = 0.55; #declare Tilt = <20, 10, 0>;  #declare Col = <0.85, 0.62, 0.18>;
  #elseif (B = 1) #declare At = < 0.4, 0, 2.6>;  #declare Sc = 0.70; #declare Tilt = <-15, 40, 8>; #declare Col = <0.75, 0.20, 0.18>;
  #elseif (B = 2) #declare At = < 2.9, 0, 0.6>;  #declare Sc = 0.50; #declare Tilt = <35, 0, 25>;  #declare Col = <0.20, 0.42, 0.78>;
  #elseif (B = 3) #declare At = <-0.7, 0, -0.6>; #declare Sc = 0.45; #declare Tilt = <0, 25, -30>; #declare Col = <0.85, 0.82, 0.70>;
  #elseif (B = 4) #declare At = <-3.6, 0, -1.4>; #declare Sc = 0.40; #declare Tilt = <50, 5, 10>;  #declare Col = <0.30, 0.62, 0.30>;
  #elseif (B = 5) #declare At = < 4.2, 0, 3.4>;  #declare Sc = 0.60; #declare Tilt = <10, 60, 40>; #declare Col = <0.62, 0.35, 0.70>;
  #else           #declare At = < 1.5, 0, -1.9>; #declare Sc = 0.38; #declare Tilt = <-30, 15, 20>; #declare Col = <0.90, 0.55, 0.40>;
  #end
  mesh {
    #declare j = 0;
    #while (j < NL)
      // rows j and j + 1: sine and cosine of the polar angle (poles exact)
      #declare s0 = sin(pi*j/NL);       #declare c0 = cos(pi*j/NL);
      #declare s1 = sin(pi*(j + 1)/NL); #declare c1 = cos(pi*(j + 1)/NL);
      #if (j = 0)      #declare s0 = 0; #declare c0 = 1;  #end
      #if (j = NL - 1) #declare s1 = 0; #declare c1 = -1; #end
      #declare sm = sin(pi*(j + 0.5)/NL); #declare cm = cos(pi*(j + 0.5)/NL);
      #declare i = 0;
      #while (i < NM)
        #declare a0 = 2*pi*i/NM; #declare a1 = 2*pi*mod(i + 1, NM)/NM; #declare am = 2*pi*(i + 0.5)/NM;
        #declare P00 = <s0*cos(a0), c0, s0*sin(a0)>;
        #declare P01 = <s0*cos(a1), c0, s0*sin(a1)>;
        #declare P10 = <s1*cos(a0), c1, s1*sin(a0)>;
        #declare P11 = <s1*cos(a1), c1, s1*sin(a1)>;
        #declare Apex = Spike*<sm*cos(am), cm, sm*sin(am)>;
        triangle { P00, P10, Apex }
        #if (j < NL - 1) triangle { P10, P11, Apex } #end
        triangle { P11, P01, Apex }
        #if (j > 0) triangle { P01, P00, Apex } #end
        #declare i = i + 1;
      #end
      #declare j = j + 1;
    #end
    pigment { color rgb Col }
    finish { phong 0.6 phong_size 60 }
    rotate Tilt
    // no spike reaches below the floor
    scale Sc translate At + (Spike*Sc + 0.02)*y
  }
  #declare B = B + 1;
#end

// ---- stellated octahedra --------------------------------------------------
// On each face of the octahedron with vertices on the axes at 1, a spike
// to the cube's corner (sx, sy, sz): the compound of two tetrahedra.
#declare NOct = 6;
#declare O = 0;
#while (O < NOct)
  #declare At = <-3.3 + 1.35*O, 0, -3.0 + 0.9*mod(O, 2) + 0.25*O>;
  #declare Sc = 0.36 + 0.05*mod(O*3, 4);
  mesh {
    #declare sx = -1;
    #while (sx < 2)
      #declare sy = -1;
      #while (sy < 2)
        #declare sz = -1;
        #while (sz < 2)
          triangle { <sx, 0, 0>, <0, sy, 0>, <sx, sy, sz> }
          triangle { <0, sy, 0>, <0, 0, sz>, <sx, sy, sz> }
          triangle { <0, 0, sz>, <sx, 0, 0>, <sx, sy, sz> }
          #declare sz = sz + 2;
        #end
        #declare sy = sy + 2;
      #end
      #declare sx = sx + 2;
    #end
    pigment { color rgb <0.35 + 0.1*O, 0.75 - 0.08*O, 0.55 + 0.05*mod(O, 3)> }
    finish { phong 0.5 phong_size 50 }
    // stand on a corner-spike: turn the diagonal (1, 1, 1) up, then spin
    rotate y*45 rotate z*-35.26439 rotate y*(17*O)
    scale Sc translate At + (sqrt(3)*Sc + 0.02)*y
  }
  #declare O = O + 1;
#end

// ---- thick five-pointed stars ---------------------------------------------
// Ten rim points alternating between radius 1 and 0.42 in the xy plane,
// and two apexes at z = +-0.28: twenty triangles.
#declare NFive = 12;
#declare F = 0;
#while (F < NFive)
  #declare At = <-4.6 + 0.85*F, 0, 5.2 - 0.9*mod(F, 3) - 0.2*F>;
  mesh {
    #declare k = 0;
    #while (k < 10)
      #declare b0 = pi/2 + 2*pi*k/10; #declare b1 = pi/2 + 2*pi*mod(k + 1, 10)/10;
      #declare r0 = 1 - 0.58*mod(k, 2); #declare r1 = 1 - 0.58*mod(k + 1, 2);
      triangle { <r0*cos(b0), r0*sin(b0), 0>, <r1*cos(b1), r1*sin(b1), 0>, <0, 0,  0.28> }
      triangle { <r0*cos(b0), r0*sin(b0), 0>, <r1*cos(b1), r1*sin(b1), 0>, <0, 0, -0.28> }
      #declare k = k + 1;
    #end
    pigment { color rgb <0.92, 0.78 - 0.03*F, 0.25 + 0.05*mod(F, 4)> }
    finish { phong 0.7 phong_size 80 }
    // standing on two points (the lower tips are at y = -0.809), turned
    rotate y*(25*F - 40) rotate x*(-8 + 4*mod(F, 3))
    scale 0.6 translate At + (0.6*0.809 + 0.03)*y
  }
  #declare F = F + 1;
#end
