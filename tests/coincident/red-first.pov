// Two boxes whose tops lie in one plane (y = 0) where they overlap, the red
// one declared first: coincident surfaces (tests/coincident.sh).
camera { location <0, 10, -1> look_at 0 angle 40 }
light_source { <3, 20, -5> rgb 1 }
box { <-1, -1, -1>, <1, 0, 1> pigment { rgb <1, 0, 0> } }
box { <-2, -0.5, -2>, <0, 0, 0> pigment { rgb <0, 0, 1> } }
