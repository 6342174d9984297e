// glasses.pov -- drinking glasses on a table, after the "Glasses" scene of
// Eo, Choi and Kyung. Written for hstrace: polygons only. Every glass is a
// closed, thick-walled solid of revolution (a faceted mesh: one profile from
// the axis under the foot, out over the rim and down the inside back to the
// axis, turned about y); four are clear or tinted glass (filter, ior 1.5),
// five are opaque. Three lights throw their shadows across the table and
// over each other. About 9,400 polygons. Written for 4:3 images.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }

camera {
  location <0.1, 3.4, -4.7>
  look_at  <-0.15, 0.40, 0.30>
  angle 48
  right x*4/3
}

light_source { <-3.2, 5.2, -2.6> color rgb <0.80, 0.76, 0.68> }   // above, left: warm
light_source { < 4.2, 3.0, -0.8> color rgb <0.36, 0.40, 0.52> }   // low, right: cool
light_source { < 1.6, 3.6, 4.0> color rgb <0.30, 0.28, 0.24> }    // behind: shadows toward the eye

background { color rgb <0.06, 0.06, 0.08> }

// ---- the room and the table -----------------------------------------------
plane { y, -2.6 pigment { color rgb <0.35, 0.33, 0.30> } }
polygon { 5, <-9, -2.6, 4.6>, <9, -2.6, 4.6>, <9, 6, 4.6>, <-9, 6, 4.6>, <-9, -2.6, 4.6>
  pigment { color rgb <0.70, 0.68, 0.62> } }
box { <-3.6, -0.12, -2.4>, <3.6, 0, 3.2>
  pigment { color rgb <0.44, 0.27, 0.15> } finish { phong 0.25 phong_size 30 } }

// ---- the glasses ------------------------------------------------------------
// Two families of profiles, point K of NP, at (R, H):
//   stemmed (wine glass, flute, goblet, cordial): a foot of radius Rb, a
//     stem up to Hs, a bowl of height Hb widening to about Rm, walls Th thick;
//   tumbler: a tapered cup from radius Rb at the bottom to Rt at the top,
//     height Ht, a base Tb thick, walls Th thick, NW rings up the wall.
// Each glass stands 0.004 above the table: a bottom face in the table's
// plane, seen through the glass, would fight with the table.
#declare NB = 11;            // rings up a stemmed glass's bowl
#declare NGlass = 9;
#declare G = 0;
#while (G < NGlass)
  // family (0 stemmed, 1 tumbler), shape, facets around, place
  #if (G = 0)      // clear wine glass
    #declare F = 0; #declare Rb = 0.40; #declare Hs = 0.70; #declare Hb = 0.86; #declare Rm = 0.42; #declare S = 22;
    #declare At = <-1.30, 0, 0.10>;
  #elseif (G = 1)  // clear tumbler, fluted (few facets)
    #declare F = 1; #declare Rb = 0.30; #declare Rt = 0.36; #declare Ht = 0.95; #declare Tb = 0.12; #declare NW = 8; #declare S = 14;
    #declare At = <0.05, 0, -0.55>;
  #elseif (G = 2)  // opaque red goblet
    #declare F = 0; #declare Rb = 0.38; #declare Hs = 0.45; #declare Hb = 0.70; #declare Rm = 0.46; #declare S = 22;
    #declare At = <1.35, 0, 0.55>;
  #elseif (G = 3)  // opaque blue enamel cup
    #declare F = 1; #declare Rb = 0.33; #declare Rt = 0.40; #declare Ht = 0.80; #declare Tb = 0.06; #declare NW = 8; #declare S = 24;
    #declare At = <-0.35, 0, 1.35>;
  #elseif (G = 4)  // green-tinted shot glass
    #declare F = 1; #declare Rb = 0.17; #declare Rt = 0.22; #declare Ht = 0.45; #declare Tb = 0.10; #declare NW = 6; #declare S = 12;
    #declare At = <1.10, 0, -1.05>;
  #elseif (G = 5)  // clear champagne flute
    #declare F = 0; #declare Rb = 0.30; #declare Hs = 0.62; #declare Hb = 1.05; #declare Rm = 0.24; #declare S = 20;
    #declare At = <-0.55, 0, -0.65>;
  #elseif (G = 6)  // opaque amber cordial
    #declare F = 0; #declare Rb = 0.26; #declare Hs = 0.36; #declare Hb = 0.42; #declare Rm = 0.27; #declare S = 24;
    #declare At = <-1.70, 0, -1.30>;
  #elseif (G = 7)  // opaque white tall tumbler
    #declare F = 1; #declare Rb = 0.26; #declare Rt = 0.30; #declare Ht = 1.30; #declare Tb = 0.06; #declare NW = 10; #declare S = 24;
    #declare At = <0.75, 0, 1.85>;
  #else            // opaque dark wine glass at the back
    #declare F = 0; #declare Rb = 0.40; #declare Hs = 0.70; #declare Hb = 0.86; #declare Rm = 0.42; #declare S = 22;
    #declare At = <-2.25, 0, 1.30>;
  #end
  #declare Th = 0.016;
  #if (F = 0) #declare NP = 10 + 2*NB; #else #declare NP = 4 + 2*NW; #end
  mesh {
    #declare K = 0;
    #while (K < NP)
      #if (F = 0)
        #if (K = 0)     #declare R = 0;        #declare H = 0;
        #elseif (K = 1) #declare R = Rb;       #declare H = 0;
        #elseif (K = 2) #declare R = Rb;       #declare H = 0.025;
        #elseif (K = 3) #declare R = 0.25*Rb;  #declare H = 0.06;
        #elseif (K < 9) // the stem, slightly waisted
          #declare T = (K - 4)/4;
          #declare R = 0.042 - 0.010*sin(pi*T); #declare H = 0.10 + T*(Hs - 0.16);
        #elseif (K < 9 + NB) // the bowl's outside, foot to rim
          #declare U = (K - 9)/(NB - 1);
          #declare R = 0.08 + (Rm - 0.08)*sin(pi/2*sqrt(U))*(1 - 0.15*U*U); #declare H = Hs + Hb*U;
        #elseif (K < 9 + 2*NB) // the bowl's inside, rim to bottom
          #declare U = 1 - (K - 9 - NB)/(NB - 1);
          #declare R = 0.08 + (Rm - 0.08)*sin(pi/2*sqrt(U))*(1 - 0.15*U*U) - Th; #declare H = Hs + 0.04 + (Hb - 0.04)*U;
        #else
          #declare R = 0;        #declare H = Hs + 0.04;
        #end
      #else
        #if (K = 0)     #declare R = 0;        #declare H = 0;
        #elseif (K = 1) #declare R = Rb;       #declare H = 0;
        #elseif (K < 2 + NW) // the outside, bottom to rim
          #declare U = (K - 1)/NW;
          #declare R = Rb + (Rt - Rb)*U; #declare H = Ht*U;
        #elseif (K < 3 + 2*NW) // the inside, rim to base
          #declare U = 1 - (K - 2 - NW)/NW;
          #declare R = Rb - Th + (Rt - Rb)*U; #declare H = Tb + (Ht - Tb)*U;
        #else
          #declare R = 0;        #declare H = Tb;
        #end
      #end
      #if (K > 0)
        // one band of the solid between the last profile point and this one
        #declare i = 0;
        #while (i < S)
          #declare a0 = 2*pi*i/S; #declare a1 = 2*pi*mod(i + 1, S)/S;
          #if (R0 > 0)
            triangle { <R0*cos(a0), H0, R0*sin(a0)>, <R0*cos(a1), H0, R0*sin(a1)>, <R*cos(a1), H, R*sin(a1)> }
          #end
          #if (R > 0)
            triangle { <R0*cos(a0), H0, R0*sin(a0)>, <R*cos(a1), H, R*sin(a1)>, <R*cos(a0), H, R*sin(a0)> }
          #end
          #declare i = i + 1;
        #end
      #end
      #declare R0 = R; #declare H0 = H;
      #declare K = K + 1;
    #end
    #if (G = 0 | G = 1 | G = 5)
      texture { pigment { color rgbf <0.97, 0.98, 1.00, 0.92> }
                finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 150 } }
      interior { ior 1.5 }
    #elseif (G = 4)
      texture { pigment { color rgbf <0.55, 0.90, 0.60, 0.85> }
                finish { ambient 0 diffuse 0.08 phong 0.8 phong_size 120 } }
      interior { ior 1.5 }
    #elseif (G = 2)
      texture { pigment { color rgb <0.62, 0.08, 0.10> } finish { phong 0.7 phong_size 80 } }
    #elseif (G = 3)
      texture { pigment { color rgb <0.15, 0.28, 0.62> } finish { phong 0.5 phong_size 60 } }
    #elseif (G = 6)
      texture { pigment { color rgb <0.80, 0.50, 0.12> } finish { phong 0.6 phong_size 80 } }
    #elseif (G = 7)
      texture { pigment { color rgb <0.88, 0.87, 0.82> } finish { phong 0.4 phong_size 50 } }
    #else
      texture { pigment { color rgb <0.22, 0.10, 0.20> } finish { phong 0.8 phong_size 100 } }
    #end
    translate At + 0.004*y
  }
  #declare G = G + 1;
#end
