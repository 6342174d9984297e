// Fading interiors of curved objects: light through a see-through sphere
// and cylinder with fade_distance, fade_power and fade_colour, seen and
// casting faded shadows (the shadow ray fades over the way it runs inside
// each). (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.4 } }
sphere { <-0.8, 1, 0>, 0.8 pigment { rgbf <1, 1, 1, 0.95> } interior { fade_distance 0.5 fade_power 2 fade_colour <0.2, 0.5, 1> } }
cylinder { <1, 0.3, -0.5>, <1.2, 1.5, 0.5>, 0.4 pigment { rgbt <1, 1, 1, 0.9> } interior { fade_distance 0.3 fade_power 1 fade_colour <1, 0.4, 0.2> } }
