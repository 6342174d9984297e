// soft.pov -- soft shadows from area lights, as POV-Ray 3.7 samples them:
// a window frame (a polygon with four holes), a mesh2 prism, two boxes and
// a tinted glass pane (a transparent occluder, which filters each sample)
// on a floor before a wall, lit by three area lights of different
// adaptive levels:
//   a warm 5x5 light, adaptive 0: the four corners, subdivided only where
//     they differ;
//   a white 9x9 light, adaptive 1: one forced subdivision, then by colour;
//   a dim blue 17x17 light, adaptive 2, with area_illumination (shaded
//     from each sample, not the centre).
// Jitter=1 (povray Declare=Jitter=1, hstrace Declare=Jitter=1) adds jitter to
// all three: POV-Ray's images then differ from run to run, and hstrace's
// match them statistically (tests/area-lights.sh).
// Written for 4:3 images (320x240, 640x480).
#version 3.7;
#ifndef (Jitter) #declare Jitter = 0; #end
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0.6, 3.4, -6.2> look_at <0.2, 0.9, 0.4> angle 52 }

light_source { <-4, 4, -2.5> rgb <1.0, 0.85, 0.7>
    area_light <1.0, 0, 0>, <0, 0, 1.0>, 5, 5 adaptive 0
    #if (Jitter) jitter #end }
light_source { <4, 3.2, -1.5> rgb 0.7
    area_light <0.8, 0, 0.3>, <0, 0.8, 0>, 9, 9 adaptive 1
    #if (Jitter) jitter #end }
light_source { <0.5, 7, -5> rgb <0.15, 0.2, 0.35>
    area_light <3, 0, 0>, <0, 0, 3>, 17, 17 adaptive 2 area_illumination
    #if (Jitter) jitter #end }

plane { y, 0 pigment { rgb <0.85, 0.82, 0.75> } finish { ambient 0.05 diffuse 0.8 } }
plane { z, 3 pigment { rgb <0.75, 0.8, 0.85> } finish { ambient 0.05 diffuse 0.8 } }

// A window frame standing upright: the outer square and four panes' holes.
polygon { 25,
    <-2.4, 0.0>, <-0.4, 0.0>, <-0.4, 2.0>, <-2.4, 2.0>, <-2.4, 0.0>
    <-2.25, 0.15>, <-1.45, 0.15>, <-1.45, 0.95>, <-2.25, 0.95>, <-2.25, 0.15>
    <-1.35, 0.15>, <-0.55, 0.15>, <-0.55, 0.95>, <-1.35, 0.95>, <-1.35, 0.15>
    <-2.25, 1.05>, <-1.45, 1.05>, <-1.45, 1.85>, <-2.25, 1.85>, <-2.25, 1.05>
    <-1.35, 1.05>, <-0.55, 1.05>, <-0.55, 1.85>, <-1.35, 1.85>, <-1.35, 1.05>
    pigment { rgb <0.55, 0.35, 0.2> } finish { ambient 0.05 diffuse 0.7 }
    rotate 20*y translate <0.2, 0.05, 1.6> }

// A triangular prism as an exporter writes a mesh2.
#declare Prism = mesh2 {
    vertex_vectors { 6, <0, 0, 0>, <1, 0, 0>, <0.5, 0.9, 0>, <0, 0, 1.2>, <1, 0, 1.2>, <0.5, 0.9, 1.2> }
    face_indices { 8, <0, 2, 1>, <3, 4, 5>, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4>, <2, 0, 3>, <2, 3, 5> }
    inside_vector y
}
object { Prism pigment { rgb <0.3, 0.6, 0.35> } finish { ambient 0.05 diffuse 0.75 phong 0.4 }
    rotate -25*y translate <0.6, 0, -0.9> }

box { <-0.3, 0, -0.3>, <0.3, 1.3, 0.3> rotate 15*y translate <2.2, 0, 0.6>
    pigment { rgb <0.7, 0.25, 0.2> } finish { ambient 0.05 diffuse 0.75 specular 0.3 } }
box { <-1.8, 0, -1.6>, <-1.0, 0.35, -0.8> pigment { rgb 0.6 } finish { ambient 0.05 diffuse 0.7 } }

// A tinted glass pane standing on the floor: it filters the light through it.
polygon { 5, <-0.5, 0>, <0.5, 0>, <0.5, 0.8>, <-0.5, 0.8>, <-0.5, 0>
    pigment { rgbf <0.5, 0.7, 1.0, 0.75> } finish { ambient 0.0 diffuse 0.2 phong 0.6 }
    rotate 60*y translate <2.6, 0, -0.6> }
