// The checker/hexagon/gradient scene of tests/modelling.sh at 24x18 pixels, where a
// hit on the plane near the horizon, 3.57e16 away, reached grid_cell_coord (issue 22).
// expect: status 0
// expect: option --width 24 --height 18
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <4, 8, -3> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [0.3 rgb <0.2,0.3,0.9>] [1 rgb <0,0,0.3>] } } }
plane { y, 0 pigment { checker rgb <1,0,0>, rgb 1 scale 0.7 rotate y*20 } }
polygon { 4, <-1,0>, <1,0>, <1,2>, <-1,2>
  pigment { hexagon rgb <0,0,1> rgb <1,1,0> rgb <0,1,0> scale 0.2 rotate x*-90 }
  translate <0,0.01,0> rotate y*30 translate x*0.5 }
box { <-2.5,0,-0.5>, <-1.5,1,0.5> pigment { gradient x color_map { [0 rgb 0] [1 rgb <1,0.5,0>] } frequency 2 } }
