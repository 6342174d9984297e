// A glass cylinder standing on a plane, seen from above: the rays refracted
// into it meet its base where the plane is (tests/coincident.sh).
camera { location <0, 4, -8> look_at <0, 1, 0> angle 50 }
light_source { <10, 50, 35> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> } }
cylinder { <0, 0, 0>, <0, 2.5, 0>, 1.2
    pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 } interior { ior 1.51 } }
