// desk.pov -- the default scene of hstrace: a desk with objects and three
// light sources, after the "Desk" scene of Eo, Choi and Kyung (Fig. 2).
// Polygons only (boxes, polygons, meshes); every shadow is a hard shadow,
// and the three lights overlap them, so shadow testing dominates the render.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }

camera {
  location <-2.2, 4.6, -7.2>
  look_at  <0.1, 2.3, 0.4>
  angle 52
  right x*image_width/image_height
}

light_source { <-4.5, 9.0, -5.0> color rgb <0.80, 0.76, 0.70> }     // ceiling, warm
light_source { < 6.0, 6.5, -3.5> color rgb <0.35, 0.40, 0.55> }     // window, cool
light_source { < 1.12, 2.80, 0.70> color rgb <0.60, 0.52, 0.30>      // the desk lamp
               fade_distance 1.5 fade_power 1 }

background { color rgb <0.05, 0.05, 0.07> }

#declare Wood  = texture { pigment { color rgb <0.45, 0.27, 0.14> } finish { phong 0.3 phong_size 30 } }
#declare Metal = texture { pigment { color rgb <0.62, 0.64, 0.66> } finish { ambient 0.05 diffuse 0.5 specular 0.6 roughness 0.02 reflection 0.15 } }
#declare Paper = texture { pigment { color rgb <0.92, 0.91, 0.86> } }

// Floor and wall
plane { y, 0 pigment { color rgb <0.55, 0.52, 0.48> } }
box { <-8, 0, 3.0>, <8, 8, 3.2> pigment { color rgb <0.78, 0.80, 0.74> } }

// The desk: top, two side panels, back panel
union {
  box { <-3.0, 2.00, -1.3>, <3.0, 2.15, 1.4> }
  box { <-2.9, 0.00, -1.2>, <-2.75, 2.00, 1.3> }
  box { < 2.75, 0.00, -1.2>, < 2.9, 2.00, 1.3> }
  box { <-2.75, 0.60, 1.15>, < 2.75, 2.00, 1.3> }
  // a drawer block on the right
  box { < 1.4, 0.90, -1.1>, < 2.75, 2.00, 1.15> }
  texture { Wood }
}
// drawer fronts and handles
#declare i = 0;
#while (i < 2)
  box { <1.45, 0.95 + i*0.52, -1.13>, <2.70, 1.42 + i*0.52, -1.10> pigment { color rgb <0.50, 0.31, 0.17> } }
  box { <1.95, 1.15 + i*0.52, -1.18>, <2.20, 1.20 + i*0.52, -1.13> texture { Metal } }
  #declare i = i + 1;
#end

// A row of books, standing and leaning
#declare i = 0;
#while (i < 7)
  #declare H = 0.62 + 0.09*sin(i*2.3);
  #declare T = 0.10 + 0.03*cos(i*1.7);
  box { <0, 0, 0>, <T, H, 0.48>
        pigment { color rgb <0.25 + 0.3*abs(sin(i*1.3)), 0.15 + 0.25*abs(cos(i*0.9)), 0.20 + 0.3*abs(sin(i*0.7))> }
        finish { phong 0.2 }
        translate <-2.70 + i*0.15, 2.15, 0.55> }
  #declare i = i + 1;
#end
box { <0, 0, 0>, <0.11, 0.66, 0.48> pigment { color rgb <0.6, 0.1, 0.1> } rotate z*-22 translate <-1.55, 2.15, 0.55> }

// A stack of papers: thin boxes, each turned a little
#declare i = 0;
#while (i < 6)
  box { <-0.45, 0, -0.32>, <0.45, 0.012, 0.32> texture { Paper } rotate y*(7*sin(i*1.9)) translate <-0.6, 2.15 + i*0.013, -0.45> }
  #declare i = i + 1;
#end
// Index cards standing against the books: single polygons
#declare i = 0;
#while (i < 4)
  polygon { 5, <0,0>, <0.5,0>, <0.5,0.32>, <0,0.32>, <0,0>
            pigment { color rgb <0.95, 0.93, 0.80 - 0.1*i> }
            rotate x*(-12 - 4*i) rotate y*(15 + 8*i) translate <-1.2 + i*0.12, 2.15, 0.2 + 0.05*i> }
  #declare i = i + 1;
#end

// A faceted vase: a solid of revolution as a mesh of triangles
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
  translate <0.45, 2.15, 0.55>
}
// Flowers' stems: thin boxes
#declare i = 0;
#while (i < 5)
  box { <-0.008, 0, -0.008>, <0.008, 0.7, 0.008> pigment { color rgb <0.2, 0.45, 0.15> }
        rotate z*(-14 + 7*i) rotate y*(37*i) translate <0.45, 3.0, 0.55> }
  #declare i = i + 1;
#end

// A pencil holder: an open faceted cylinder (no top), with pencils
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
  translate <-0.35, 2.15, 0.75>
}
#declare i = 0;
#while (i < 6)
  box { <-0.018, 0, -0.018>, <0.018, 0.75, 0.018>
        pigment { color rgb <0.9, 0.75 - 0.1*i, 0.1 + 0.12*i> }
        rotate z*(-10 + 4*i) rotate y*(60*i) translate <-0.35 + 0.06*cos(i), 2.17, 0.75 + 0.06*sin(i)> }
  #declare i = i + 1;
#end

// The desk lamp: base, two arms, a faceted conical shade
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

// A chair in front of the desk
union {
  box { <-0.75, 1.15, -0.7>, <0.75, 1.25, 0.7> }
  box { <-0.75, 1.25, 0.6>, <0.75, 2.9, 0.7> }
  #declare i = 0;
  #while (i < 4)
    box { <-0.06, 0, -0.06>, <0.06, 1.15, 0.06> translate <(i < 2 ? -0.65 : 0.65), 0, (mod(i, 2) = 0 ? -0.6 : 0.6)> }
    #declare i = i + 1;
  #end
  pigment { color rgb <0.30, 0.18, 0.10> }
  finish { phong 0.2 }
  rotate y*140
  translate <-2.9, 0, -2.3>
}
