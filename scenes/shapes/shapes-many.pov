// Many shapes: 1600 spheres and 229 cylinders on a floor, for the
// shapes' own hierarchy (bvh.h's Bvh.shapes) that camera, secondary and
// shadow rays walk. (tests/shapes.sh, tests/test_bvh.c)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -18> look_at <0, 0, 0> angle 50 }
light_source { <10, 20, -10> color rgb 1 }
light_source { <-12, 8, -4> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
#declare I = 0;
#while (I < 40)
  #declare J = 0;
  #while (J < 40)
    sphere { <I - 19.5, 0.3 + 0.2 * sin(I * J), J - 19.5>, 0.35 pigment { rgb <I / 40, J / 40, 0.5> } }
    #if (mod(I + J, 7) = 0) cylinder { <I - 19.5, 0, J - 19.5>, <I - 19.5, 1.2, J - 19.5>, 0.1 pigment { rgb 1 } } #end
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
