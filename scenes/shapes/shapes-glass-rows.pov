// Rows of see-through spheres and cylinders, some with fading interiors,
// between two point lights and the floor and wall: the first light lies
// far down the rows, so shadow rays cross up to some 24 of them, and the
// light buffer's cells list many curved objects and fold the see-through
// ones crossed in the walk's order, or leave more than they fold to the
// walk (shadow_light_buffer.c); a few opaque ones stand in one row.
// Every method must give the shadow ray's colour, bit for bit.
// (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 24, -3> look_at <0, 0, 1.5> angle 55 }
light_source { <0.3, 1.7, -120> color rgb 1 }
light_source { <6, 14, 4> color rgb 0.5 }
plane { y, 0 pigment { rgb 0.9 } }
plane { z, 12 pigment { rgb 0.8 } }
#declare I = 0;
#while (I < 24)
  #declare J = 0;
  #while (J < 5)
    #if (J = 4 & mod(I, 7) = 3)
      sphere { <J * 1.3 - 2.6, 1 + 0.3 * J, I * 0.9 - 9>, 0.42 pigment { rgb <0.3, 0.2, 0.6> } }
    #else
      sphere { <J * 1.3 - 2.6, 1 + 0.3 * J, I * 0.9 - 9>, 0.42
        pigment { rgbf <1 - J * 0.1, 0.9, 0.6 + 0.05 * mod(I, 5), 0.95> }
        #if (mod(I, 4) = 1) interior { fade_distance 2 fade_power 2 fade_color rgb <0.4, 0.9, 0.5> } #end }
    #end
    #declare J = J + 1;
  #end
  #if (mod(I, 3) = 0)
    cylinder { <-4, 0.2, I * 0.9 - 9>, <4, 0.2, I * 0.9 - 9>, 0.12 pigment { rgbt <0.8, 0.5, 0.3, 0.7> } }
  #end
  #declare I = I + 1;
#end
