// interior_texture on the swept and curved shapes whose normals hstrace
// computes as POV-Ray's (prism.cpp, lathe.cpp, sor.cpp,
// superellipsoid.cpp): prisms of either winding, linear, cubic and conic,
// one inverted and mirrored; a lathe, a sor and a superellipsoid, clipped
// or cut open so that their insides show, one inverted
// (tests/layered-textures.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <5, 10, -5> rgb 1 }
light_source { <-5, -6, -3> rgb 0.5 }
plane { y, -2 pigment { checker rgb 0.8 rgb 0.4 } }
#declare T = texture { pigment { rgb <0.9, 0.6, 0.2> } }
#declare I = texture { pigment { rgb <0.2, 0.5, 0.9> } }
prism { linear_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0.3 } } translate <-2.5, 0, 0> }
prism { linear_sweep linear_spline 0, 0.6, 5, <-1, -1>, <-1, 1>, <1, 1>, <1, -1>, <-1, -1>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0.3 } } scale 0.5 translate <-2.5, 1.3, -0.5> }
prism { linear_sweep cubic_spline -0.5, 1, 7, <0, -1>, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0.3 } } rotate 20*y }
prism { linear_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
    inverse texture { T } interior_texture { I } clipped_by { plane { -z, 0.3 } } scale <0.4, -0.4, 0.4>
    translate <0, 2, -1> }
prism { conic_sweep linear_spline 0.3, 1, 4, <0, 0>, <1, 1>, <-1, 1>, <0, 0>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0.2 } } rotate 180*x translate <2.5, 1.5, 0> }
lathe { cubic_spline 6, <0.2, -1>, <0.8, -0.5>, <0.6, 0>, <0.9, 0.6>, <0.5, 1>, <0.1, 1.2>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0 } } translate <-1.3, 0, -2> }
sor { 6, <0.2, -1>, <0.8, -0.5>, <0.6, 0>, <0.9, 0.6>, <0.5, 1>, <0.1, 1.2>
    texture { T } interior_texture { I } clipped_by { plane { -z, 0 } } translate <1.3, 0, -2> }
superellipsoid { <0.5, 0.3> inverse texture { T } interior_texture { I } clipped_by { plane { -z, 0 } }
    scale 0.6 translate <0, -1, -2> }
