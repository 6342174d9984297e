// merge: see-through spheres merged (no surfaces inside the solid: a
// crossing of one part counts where the point is inside no other part)
// beside a union of the same spheres (whose inner surfaces show), a glass
// merge refracting, and filtered shadows of both. (tests/csg.sh)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 55 }
light_source { <2, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
merge {
    sphere { <-2, 1, 0>, 0.8 }
    sphere { <-1.3, 1, 0>, 0.8 }
    cylinder { <-1.65, 0.2, 0>, <-1.65, 1.6, 0>, 0.3 }
    pigment { rgbf <1, 0.6, 0.6, 0.7> }
}
union {
    sphere { <0.3, 1, 0>, 0.8 }
    sphere { <1, 1, 0>, 0.8 }
    pigment { rgbf <0.6, 0.6, 1, 0.7> }
}
merge {
    sphere { <1.9, 0.5, -1.5>, 0.5 }
    sphere { <2.3, 0.5, -1.3>, 0.45 }
    pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.4 }
}
