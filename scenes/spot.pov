// spot.pov -- an area spotlight, circular and oriented, as POV-Ray 3.7
// samples it: an 8x8 circular area_light with orient (the disc turned to
// face every shading point) and adaptive 1 in a spotlight's cone, above a
// lattice (a polygon with nine square holes) held over the floor and a
// mesh2 crown written as an exporter writes one (a ring of 48 triangles);
// and a low parallel area light, 4x4 with adaptive 0, for long soft
// shadows from the side.
// Jitter=1 (povray Declare=Jitter=1, hstrace Declare=Jitter=1) adds jitter to
// both: POV-Ray's images then differ from run to run, and hstrace's match
// them statistically (tests/area-lights.sh).
// Written for 4:3 images (320x240, 640x480).
#version 3.7;
#ifndef (Jitter) #declare Jitter = 0; #end
global_settings { assumed_gamma 1.0 }
camera { location <0, 5.5, -6> look_at <0, 0.4, 0> angle 48 }

light_source { <0.5, 6, 0.5> rgb 1.3
    spotlight point_at <0, 0, 0> radius 28 falloff 40 tightness 2
    area_light <1.5, 0, 0>, <0, 0, 1.5>, 8, 8 circular orient adaptive 1
    #if (Jitter) jitter #end }
light_source { <-8, 2.5, 3> rgb <0.35, 0.3, 0.25> parallel point_at <0, 0, 0>
    area_light <0, 0.8, 0>, <0, 0, 0.8>, 4, 4 adaptive 0
    #if (Jitter) jitter #end }

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.08 diffuse 0.8 } }

// A lattice: a square with a 3x3 grid of square holes, held level.
#declare Lattice = polygon { 50,
    <-1.2, -1.2>, <1.2, -1.2>, <1.2, 1.2>, <-1.2, 1.2>, <-1.2, -1.2>
    #declare I = 0;
    #while (I < 3)
        #declare J = 0;
        #while (J < 3)
            #declare X = -1.05 + I * 0.75;
            #declare Y = -1.05 + J * 0.75;
            <X, Y>, <X + 0.6, Y>, <X + 0.6, Y + 0.6>, <X, Y + 0.6>, <X, Y>
            #declare J = J + 1;
        #end
        #declare I = I + 1;
    #end
}
object { Lattice pigment { rgb <0.75, 0.6, 0.35> } finish { ambient 0.05 diffuse 0.7 }
    rotate 90*x rotate 20*y translate <-1.2, 1.3, 0.2> }
box { <-0.05, 0, -0.05>, <0.05, 1.3, 0.05> translate <-1.2, 0, 0.2> pigment { rgb 0.4 } }

// A crown: a ring of zigzag triangles.
#declare N = 24;
#declare Crown = mesh2 {
    vertex_vectors { 2 * N,
        #declare K = 0;
        #while (K < N)
            <0.7 * cos(2 * pi * K / N), 0, 0.7 * sin(2 * pi * K / N)>,
            <0.7 * cos(2 * pi * (K + 0.5) / N), 0.8, 0.7 * sin(2 * pi * (K + 0.5) / N)>
            #declare K = K + 1;
        #end
    }
    face_indices { 2 * N,
        #declare K = 0;
        #while (K < N)
            <2 * K, 2 * K + 1, mod(2 * K + 2, 2 * N)>,
            <2 * K + 1, mod(2 * K + 3, 2 * N), mod(2 * K + 2, 2 * N)>
            #declare K = K + 1;
        #end
    }
}
object { Crown pigment { rgb <0.8, 0.7, 0.2> } finish { ambient 0.05 diffuse 0.7 phong 0.6 metallic 0.5 }
    rotate 5*y translate <1.3, 0, -0.4> }
box { <-0.4, 0, -0.4>, <0.4, 0.5, 0.4> rotate 30*y translate <0.2, 0, -1.6>
    pigment { rgb <0.3, 0.45, 0.7> } finish { ambient 0.05 diffuse 0.75 specular 0.4 } }
