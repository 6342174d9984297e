// A cylinder standing on a plane, seen from below: its base lies in the
// plane, a curved object's surface coincident with a plane's
// (tests/coincident.sh).
camera { location <0, -3, -6> look_at <0, 0, 0> }
light_source { <3, -10, -5> rgb 1 }
plane { y, 0 pigment { rgb <0, 0, 1> } }
cylinder { <0, 0, 0>, <0, 2, 0>, 1.5 pigment { rgb <1, 0, 0> } }
