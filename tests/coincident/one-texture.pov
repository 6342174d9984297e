// red-first.pov's boxes as one union's parts under the union's texture: one
// texture placed alike, nothing to tell apart (tests/coincident.sh).
camera { location <0, 10, -1> look_at 0 angle 40 }
light_source { <3, 20, -5> rgb 1 }
union {
    box { <-1, -1, -1>, <1, 0, 1> }
    box { <-2, -0.5, -2>, <0, 0, 0> }
    pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> scale 0.5 }
}
