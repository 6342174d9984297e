// interior-texture-swept.pov's prisms seen from below: POV-Ray's prism
// normal faces +y on both caps and by the outline's winding on the sides, so
// the base shows the interior texture from outside, and one prism's sides
// too (tests/layered-textures.sh).
camera { location <0, -4, -5> look_at 0 }
light_source { <5, -10, -5> rgb 1 }
prism { linear_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  texture { pigment { rgb <0.9, 0.6, 0.2> } } interior_texture { pigment { rgb <0.2, 0.5, 0.9> } } translate -1.5*x }
prism { linear_sweep linear_spline 0, 1, 5, <-1, -1>, <-1, 1>, <1, 1>, <1, -1>, <-1, -1>
  texture { pigment { rgb <0.9, 0.6, 0.2> } } interior_texture { pigment { rgb <0.2, 0.5, 0.9> } } translate 1.5*x }
