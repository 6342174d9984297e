// uv_mapping on spheres as POV-Ray defines it (Sphere::UVCoord): a
// checker and a gradient in (u, v), on a plain sphere and on a moved and
// uniformly scaled one, lit by ambient alone. (tests/shapes.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <3, 6, -5> color rgb 1 }
sphere { <-1.2, 0.6, 0>, 1 uv_mapping pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.3, 0.9> scale <0.125, 0.25, 1> } finish { ambient 1 diffuse 0 } }
sphere { 0, 0.5 uv_mapping pigment { gradient x color_map { [0 rgb <0, 0.5, 0>] [1 rgb <1, 1, 0>] } } finish { ambient 1 diffuse 0 } rotate <20, 40, 0> scale 1.8 translate <1.3, 0.9, 0.5> }
