// Spherical components in both syntaxes (component and sphere with and
// without the strength keyword), one of negative strength carving a dent,
// translated, rotated and uniformly scaled, the blob casting a shadow on
// the floor and on itself (tests/blob.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 7, -3>, rgb 1 }
light_source { <5, 4, -5>, rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.55 } }
blob {
  threshold 0.6
  component 1.0, 1.0, <0.75, 0, 0>
  component 1.0, 1.0, <-0.375, 0.64952, 0>
  sphere { <-0.375, -0.64952, 0>, 1, 1 }
  sphere { <0, 0, -0.6>, 0.7, strength -1.5 }
  sphere { <0, 0.2, 0>, 0.5, 1 translate <0, 0.3, 0.4> rotate y * 30 scale 1.5 }
  pigment { rgb <0.9, 0.35, 0.2> }
  finish { phong 0.6 }
  rotate x * -20
  translate <0, 1.2, 0>
}
sphere { <2.2, 0.5, 0.5>, 0.5 pigment { rgb <0.3, 0.6, 0.9> } }
