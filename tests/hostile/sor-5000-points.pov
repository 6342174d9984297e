// A sor of 5000 points: every ray solved all 4997 segments' cubics, with
// sturm, and with a light 64 pilot rays planning its shadows did too (85 s
// at 1x1 under the sanitizers; POV-Ray, whose bounding cylinders pick the
// segments to test, renders it in under a second). Only the segments
// whose heights and radii the ray reaches are solved for now.
// expect: status 0
camera { location <0, 1, -5> look_at 0 }
light_source { <2, 4, -3>, 1 }
sor { 5000 #for (I, 0, 4999) , <1 + sin(I), I / 1000> #end sturm pigment { rgb 1 } }
