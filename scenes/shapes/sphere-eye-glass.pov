// The eye inside a see-through sphere with an interior: camera rays start
// inside its interior (refraction at its surface from ior 1.3 to 1, light
// faded on the way out, shadow rays fading from their start), as POV-Ray's
// InitRayContainerState finds by the sphere's inside test. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -2> look_at <0, 0.5, 2> angle 60 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb <0.2, 0.3, 0.5> } }
sphere { <0, 1, 1>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <0, 1, -2>, 1.5 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.3 fade_distance 2 fade_power 1 fade_colour <0.5, 0.7, 1> } }
