// tiles { texture { } tile2 texture { } } (POV-Ray's Parse_Tiles: a checker
// of two textures, the first tile where the checker is 1), moved by the
// transforms after it, on a box and on a sphere casting its shadow on it;
// a tile's texture patterned, with its own finish and normal
// (tests/layered-textures.sh).
camera { location <0, 4, -6> look_at <0, 0.3, 0> }
light_source { <3, 10, -5> rgb 1 }
box { <-3, -1, -3>, <3, 0, 3>
    texture {
        tiles {
            texture { pigment { rgb <1, 0.2, 0.2> } finish { phong 0.5 } }
            tile2 texture { pigment { granite color_map { [0 rgb 0.1] [1 rgb 1] } } normal { bumps 0.3 scale 0.2 } }
        }
        scale 0.75
        rotate 20*y
    }
}
sphere { <0, 1, 0>, 1
    texture { tiles { texture { pigment { rgb <0, 1, 0> } } tile2 texture { pigment { rgbf <1, 1, 1, 0.6> } } } scale 0.3 }
}
