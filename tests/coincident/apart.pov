// Two boxes whose tops lie in one plane but do not overlap: nothing
// coincides (tests/coincident.sh).
camera { location <0, 10, -1> look_at 0 angle 40 }
light_source { <3, 20, -5> rgb 1 }
box { <-2, -1, -1>, <-0.5, 0, 1> pigment { rgb <1, 0, 0> } }
box { <0, -0.5, -2>, <2, 0, 0> pigment { rgb <0, 0, 1> } }
