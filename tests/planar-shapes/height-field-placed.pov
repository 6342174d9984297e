// Height fields placed by transforms, one cut by its water level, from an
// 8-bit grey PGM, an 8-bit colour PNG (red the high byte, green the low) and
// a palette PNG (its indices the heights), smooth and not, lit to shadow
// each other (tests/planar-shapes.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4.5> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 4, -2>, rgb 1 }
height_field {
  pgm "hf-pgm.pgm" water_level 0.3 smooth
  translate <-0.5, 0, -0.5> scale <2.5, 0.6, 1.8> rotate y * 30 translate <-0.9, 0, 0.3>
  pigment { rgb <0.7, 0.8, 0.5> }
}
height_field {
  png "hf-png8.png"
  scale <1.5, 0.8, 1.5> rotate <0, -40, 10> translate <0.6, 0.2, -0.6>
  pigment { rgb <0.9, 0.5, 0.4> }
  finish { phong 0.4 }
}
height_field {
  png "hf-pal.png" smooth
  scale <1.2, 0.5, 0.9> rotate y * 70 translate <-1.6, 0, -1.4>
  pigment { rgb <0.6, 0.6, 0.9> }
}
plane { y, 0 pigment { rgb <0.4, 0.5, 0.6> } }
