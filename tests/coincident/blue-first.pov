// red-first.pov with the boxes in the other order (tests/coincident.sh).
camera { location <0, 10, -1> look_at 0 angle 40 }
light_source { <3, 20, -5> rgb 1 }
box { <-2, -0.5, -2>, <0, 0, 0> pigment { rgb <0, 0, 1> } }
box { <-1, -1, -1>, <1, 0, 1> pigment { rgb <1, 0, 0> } }
