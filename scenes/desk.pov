// desk.pov -- the default scene of hstrace: a desk with objects on it, lit by
// three point lights, after the "Desk" scene of Eo, Choi and Kyung (Fig. 2).
// Polygons only (boxes, polygons, meshes); every shadow is a hard shadow and
// the three lights overlap them, so shadow testing dominates the render.
// About 3,900 polygons; the faceted vase and mug are meshes of revolution.
// Written for 4:3 images (320x240, 640x480).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }

camera {
  location <-1.4, 4.9, -5.6>
  look_at  <0.15, 2.35, 0.45>
  angle 50
  right x*4/3
}

light_source { <-4.0, 9.0, -4.5> color rgb <0.78, 0.74, 0.66> }     // ceiling, warm
light_source { < 6.5, 5.5, -3.0> color rgb <0.34, 0.40, 0.56> }     // window, cool
light_source { < 1.12, 2.80, 0.70> color rgb <0.70, 0.58, 0.32>      // the desk lamp
               fade_distance 1.6 fade_power 1 }

background { color rgb <0.05, 0.05, 0.07> }

#declare Wood  = texture { pigment { color rgb <0.46, 0.28, 0.15> } finish { phong 0.3 phong_size 30 } }
#declare DarkWood = texture { pigment { color rgb <0.30, 0.17, 0.09> } finish { phong 0.2 } }
#declare Metal = texture { pigment { color rgb <0.62, 0.64, 0.66> }
                           finish { ambient 0.05 diffuse 0.5 specular 0.6 roughness 0.02 reflection 0.15 } }
#declare Paper = texture { pigment { color rgb <0.92, 0.91, 0.86> } }
#declare Plastic = texture { pigment { color rgb <0.16, 0.17, 0.19> } finish { phong 0.3 phong_size 40 } }

// ---- the room: floor, rug, wall, skirting board, a picture ---------------
plane { y, 0 pigment { color rgb <0.50, 0.47, 0.43> } }
box { <-3.6, 0, -3.2>, <3.4, 0.02, 1.0> pigment { color rgb <0.42, 0.16, 0.14> } }
box { <-8, 0, 3.0>, <8, 8, 3.2> pigment { color rgb <0.80, 0.80, 0.72> } }
box { <-8, 0, 2.94>, <8, 0.25, 3.0> texture { DarkWood } }
// a picture frame: one polygon with a hole, and the picture behind it
polygon { 10,
  <-0.8, -0.6>, <0.8, -0.6>, <0.8, 0.6>, <-0.8, 0.6>, <-0.8, -0.6>,
  <-0.65, -0.45>, <0.65, -0.45>, <0.65, 0.45>, <-0.65, 0.45>, <-0.65, -0.45>
  texture { DarkWood }
  translate <-1.1, 3.95, 2.90> }
polygon { 5, <-0.65, -0.45>, <0.65, -0.45>, <0.65, 0.45>, <-0.65, 0.45>, <-0.65, -0.45>
  pigment { color rgb <0.25, 0.45, 0.60> }
  translate <-1.1, 3.95, 2.96> }
polygon { 4, <-0.65, -0.45>, <0.65, -0.45>, <-0.05, 0.25>, <-0.65, -0.45>
  pigment { color rgb <0.30, 0.50, 0.25> }
  translate <-1.1, 3.95, 2.93> }
// the frame stands off the wall on four small blocks, their fronts just
// behind the frame's back (faces in one plane would be coincident surfaces)
#declare Standoff = box { <-0.05, -0.05, 0.001>, <0.05, 0.05, 0.10> texture { DarkWood } }
object { Standoff translate <-1.82, 3.43, 2.90> }
object { Standoff translate <-1.82, 4.47, 2.90> }
object { Standoff translate <-0.38, 3.43, 2.90> }
object { Standoff translate <-0.38, 4.47, 2.90> }

// ---- the desk: top, side panels, back panel, drawer block -----------------
union {
  box { <-3.0, 2.00, -1.3>, <3.0, 2.15, 1.4> }
  box { <-2.9, 0.00, -1.2>, <-2.75, 2.00, 1.3> }
  box { < 2.75, 0.00, -1.2>, < 2.9, 2.00, 1.3> }
  box { <-2.75, 0.60, 1.15>, < 2.75, 2.00, 1.3> }
  box { < 1.4, 0.90, -1.1>, < 2.75, 2.00, 1.15> }
  texture { Wood }
}
#declare i = 0;
#while (i < 2)
  box { <1.45, 0.95 + i*0.52, -1.13>, <2.70, 1.42 + i*0.52, -1.10> pigment { color rgb <0.52, 0.32, 0.18> } }
  box { <1.90, 1.15 + i*0.52, -1.19>, <2.25, 1.21 + i*0.52, -1.13> texture { Metal } }
  #declare i = i + 1;
#end

// ---- books: a row standing, one leaning, two lying -------------------------
#declare i = 0;
#while (i < 7)
  #declare H = 0.62 + 0.09*sin(i*2.3);
  #declare T = 0.10 + 0.03*cos(i*1.7);
  box { <0, 0, 0>, <T, H, 0.48>
        pigment { color rgb <0.25 + 0.3*abs(sin(i*1.3)), 0.15 + 0.25*abs(cos(i*0.9)), 0.20 + 0.3*abs(sin(i*0.7))> }
        finish { phong 0.2 }
        translate <-2.75 + i*0.15, 2.15, 0.60> }
  #declare i = i + 1;
#end
box { <0, 0, 0>, <0.11, 0.66, 0.48> pigment { color rgb <0.62, 0.10, 0.10> } rotate z*-24 translate <-1.62, 2.15, 0.60> }
box { <-0.40, 0, -0.28>, <0.40, 0.10, 0.28> pigment { color rgb <0.15, 0.25, 0.45> } finish { phong 0.2 }
      rotate y*8 translate <-2.25, 2.15, -0.55> }
box { <-0.34, 0, -0.24>, <0.34, 0.08, 0.24> pigment { color rgb <0.70, 0.55, 0.20> } finish { phong 0.2 }
      rotate y*-14 translate <-2.22, 2.25, -0.52> }

// ---- a writing pad and index cards ----------------------------------------
box { <-0.42, 0, -0.30>, <0.42, 0.05, 0.30> texture { Paper } rotate y*-6 translate <-0.95, 2.15, -0.55> }
box { <-0.40, 0, -0.29>, <0.40, 0.03, 0.29> pigment { color rgb <0.95, 0.94, 0.70> } rotate y*11 translate <-0.90, 2.20, -0.58> }
#declare i = 0;
#while (i < 4)
  polygon { 5, <0, 0>, <0.5, 0>, <0.5, 0.32>, <0, 0.32>, <0, 0>
            pigment { color rgb <0.95, 0.93 - 0.05*i, 0.80 - 0.12*i> }
            rotate x*(-14 - 5*i) rotate y*(10 + 7*i) translate <-1.25 + i*0.13, 2.15, 0.25 + 0.05*i> }
  #declare i = i + 1;
#end

// ---- a keyboard: a base and 4 rows of keys --------------------------------
union {
  box { <-0.80, 0, -0.26>, <0.80, 0.05, 0.26> texture { Plastic } }
  #declare r = 0;
  #while (r < 4)
    #declare k = 0;
    #while (k < 12)
      box { <-0.052, 0, -0.045>, <0.052, 0.035, 0.045> pigment { color rgb <0.78, 0.78, 0.76> }
            translate <-0.715 + k*0.13 + 0.03*r, 0.05, 0.165 - r*0.11> }
      #declare k = k + 1;
    #end
    #declare r = r + 1;
  #end
  box { <-0.40, 0.05, -0.045>, <0.40, 0.085, 0.045> pigment { color rgb <0.78, 0.78, 0.76> } translate <0.05, 0, -0.275 + 0.06> }
  rotate y*4
  translate <0.55, 2.15, -0.75>
}

// ---- a faceted vase with stems: a solid of revolution as a triangle mesh --
#declare Segs = 40;
#declare Rings = 24;
mesh {
  #declare j = 0;
  #while (j < Rings)
    #declare y0 = j/Rings;       #declare y1 = (j+1)/Rings;
    #declare r0 = 0.16 + 0.14*sin(pi*y0*1.2) + 0.05*y0*y0;
    #declare r1 = 0.16 + 0.14*sin(pi*y1*1.2) + 0.05*y1*y1;
    #declare i = 0;
    #while (i < Segs)
      #declare a0 = 2*pi*i/Segs; #declare a1 = 2*pi*(i+1)/Segs;
      triangle { <r0*cos(a0), y0, r0*sin(a0)>, <r0*cos(a1), y0, r0*sin(a1)>, <r1*cos(a1), y1, r1*sin(a1)> }
      triangle { <r0*cos(a0), y0, r0*sin(a0)>, <r1*cos(a1), y1, r1*sin(a1)>, <r1*cos(a0), y1, r1*sin(a0)> }
      #declare i = i + 1;
    #end
    #declare j = j + 1;
  #end
  pigment { color rgb <0.15, 0.35, 0.55> }
  finish { phong 0.6 phong_size 60 reflection 0.05 }
  scale <1, 0.95, 1>
  translate <0.35, 2.15, 0.65>
}
// stems and leaves (2 px wide at 320x240, so no sub-pixel slivers)
#declare i = 0;
#while (i < 5)
  box { <-0.016, 0, -0.016>, <0.016, 0.75, 0.016> pigment { color rgb <0.20, 0.45, 0.15> }
        rotate z*(-16 + 8*i) rotate y*(37*i) translate <0.35, 2.95, 0.65> }
  polygon { 5, <0, 0>, <0.12, 0.05>, <0.24, 0>, <0.12, -0.05>, <0, 0>
            pigment { color rgb <0.25, 0.55, 0.18> }
            rotate x*90 rotate z*(20 + 10*i) rotate y*(72*i + 20)
            translate <0.35 + 0.12*sin(i*1.1), 3.45 + 0.05*i, 0.65 + 0.12*cos(i*1.1)> }
  #declare i = i + 1;
#end

// ---- a mug: outer and inner walls, a rim, a bottom, a handle --------------
#declare Segs = 28;
#declare Rings = 8;
mesh {
  #declare j = 0;
  #while (j < Rings)
    #declare y0 = 0.34*j/Rings; #declare y1 = 0.34*(j+1)/Rings;
    #declare i = 0;
    #while (i < Segs)
      #declare a0 = 2*pi*i/Segs; #declare a1 = 2*pi*(i+1)/Segs;
      #declare ro = 0.15;  #declare ri = 0.13;
      triangle { <ro*cos(a0), y0, ro*sin(a0)>, <ro*cos(a1), y0, ro*sin(a1)>, <ro*cos(a1), y1, ro*sin(a1)> }
      triangle { <ro*cos(a0), y0, ro*sin(a0)>, <ro*cos(a1), y1, ro*sin(a1)>, <ro*cos(a0), y1, ro*sin(a0)> }
      triangle { <ri*cos(a0), y0 + 0.02, ri*sin(a0)>, <ri*cos(a1), y0 + 0.02, ri*sin(a1)>, <ri*cos(a1), y1, ri*sin(a1)> }
      triangle { <ri*cos(a0), y0 + 0.02, ri*sin(a0)>, <ri*cos(a1), y1, ri*sin(a1)>, <ri*cos(a0), y1, ri*sin(a0)> }
      #if (j = Rings - 1)
        triangle { <ro*cos(a0), y1, ro*sin(a0)>, <ro*cos(a1), y1, ro*sin(a1)>, <ri*cos(a1), y1, ri*sin(a1)> }
        triangle { <ro*cos(a0), y1, ro*sin(a0)>, <ri*cos(a1), y1, ri*sin(a1)>, <ri*cos(a0), y1, ri*sin(a0)> }
      #end
      #if (j = 0)
        triangle { <0, 0.02, 0>, <ri*cos(a0), 0.02, ri*sin(a0)>, <ri*cos(a1), 0.02, ri*sin(a1)> }
      #end
      #declare i = i + 1;
    #end
    #declare j = j + 1;
  #end
  pigment { color rgb <0.88, 0.86, 0.80> }
  finish { phong 0.5 phong_size 50 }
  translate <-0.05, 2.15, -0.20>
}
#declare i = 0;
#while (i < 7)
  #declare a0 = -pi/2 + pi*i/7;  #declare a1 = -pi/2 + pi*(i+1)/7;
  polygon { 5, <0.15 + 0.10*cos(a0), 0.17 + 0.10*sin(a0)>, <0.15 + 0.10*cos(a1), 0.17 + 0.10*sin(a1)>,
               <0.15 + 0.06*cos(a1), 0.17 + 0.06*sin(a1)>, <0.15 + 0.06*cos(a0), 0.17 + 0.06*sin(a0)>,
               <0.15 + 0.10*cos(a0), 0.17 + 0.10*sin(a0)>
            pigment { color rgb <0.88, 0.86, 0.80> }
            rotate y*25 translate <-0.05, 2.15, -0.20> }
  #declare i = i + 1;
#end

// ---- a pencil holder: an open faceted cylinder, with pencils --------------
#declare Segs = 24;
mesh {
  #declare i = 0;
  #while (i < Segs)
    #declare a0 = 2*pi*i/Segs; #declare a1 = 2*pi*(i+1)/Segs;
    triangle { <0.16*cos(a0), 0, 0.16*sin(a0)>, <0.16*cos(a1), 0, 0.16*sin(a1)>, <0.16*cos(a1), 0.42, 0.16*sin(a1)> }
    triangle { <0.16*cos(a0), 0, 0.16*sin(a0)>, <0.16*cos(a1), 0.42, 0.16*sin(a1)>, <0.16*cos(a0), 0.42, 0.16*sin(a0)> }
    triangle { <0, 0, 0>, <0.16*cos(a0), 0, 0.16*sin(a0)>, <0.16*cos(a1), 0, 0.16*sin(a1)> }
    #declare i = i + 1;
  #end
  texture { Metal }
  translate <-0.45, 2.15, 0.80>
}
#declare i = 0;
#while (i < 6)
  box { <-0.022, 0, -0.022>, <0.022, 0.75, 0.022>
        pigment { color rgb <0.9, 0.75 - 0.1*i, 0.1 + 0.12*i> }
        rotate z*(-10 + 4*i) rotate y*(60*i) translate <-0.45 + 0.06*cos(i), 2.17, 0.80 + 0.06*sin(i)> }
  #declare i = i + 1;
#end

// ---- the desk lamp: base, two arms, a faceted conical shade ---------------
union {
  box { <-0.28, 0, -0.22>, <0.28, 0.06, 0.22> }
  box { <-0.03, 0, -0.03>, <0.03, 1.1, 0.03> rotate z*-18 translate <0, 0.06, 0> }
  box { <-0.03, 0, -0.03>, <0.03, 0.9, 0.03> rotate z*110 translate <0.34, 1.1, 0> }
  texture { Metal }
  translate <1.6, 2.15, 0.7>
}
#declare Segs = 32;
mesh {
  #declare i = 0;
  #while (i < Segs)
    #declare a0 = 2*pi*i/Segs; #declare a1 = 2*pi*(i+1)/Segs;
    triangle { <0.07*cos(a0), 0, 0.07*sin(a0)>, <0.07*cos(a1), 0, 0.07*sin(a1)>, <0.32*cos(a1), -0.38, 0.32*sin(a1)> }
    triangle { <0.07*cos(a0), 0, 0.07*sin(a0)>, <0.32*cos(a1), -0.38, 0.32*sin(a1)>, <0.32*cos(a0), -0.38, 0.32*sin(a0)> }
    #declare i = i + 1;
  #end
  pigment { color rgb <0.75, 0.12, 0.08> }
  finish { phong 0.5 }
  translate <1.12, 3.00, 0.70>
}
