// mirrors.pov -- hard case 11: two mirrors facing each other.
// Two parallel mirrors (reflection 0.95) 4 apart, with a pyramid, a block
// and a card between them on a floor, lit by two lights between the
// mirrors; max_trace_level 10, so a camera ray bounces up to nine times
// and the shadows on the floor are seen in a corridor of reflections.
// Every reflected segment starts on a mirror and carries its depth counts
// from there; a point reached through many segments is decided from counts
// carried along all of them. Stresses: long chains of segments (sustain,
// counts carried from mirror to mirror), shading points on the mirrors
// themselves (shadowed parts of a mirror still reflect), adc_bailout.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }

camera { location <-1.6, 1.25, -1.9> look_at <2, 0.9, -0.3> angle 65 right x*4/3 }

light_source { <0.4, 3.2, -0.8> color rgb <0.75, 0.72, 0.65> }
light_source { <-1.5, 1.8, 1.8> color rgb <0.25, 0.30, 0.40> }

background { color rgb <0.10, 0.12, 0.18> }
polygon { 5, <-2, 0, -6>, <2, 0, -6>, <2, 0, 6>, <-2, 0, 6>, <-2, 0, -6>
  pigment { color rgb <0.78, 0.76, 0.72> } }

#declare Mirror = texture { pigment { color rgb <0.05, 0.05, 0.06> }
                            finish { ambient 0 diffuse 0.1 reflection 0.95 } }
polygon { 5, <-2, 0, -5>, <-2, 0, 5>, <-2, 2.6, 5>, <-2, 2.6, -5>, <-2, 0, -5> texture { Mirror } }
polygon { 5, <2, 0, -5>, <2, 0, 5>, <2, 2.6, 5>, <2, 2.6, -5>, <2, 0, -5> texture { Mirror } }

// Between the mirrors: a pyramid, a block and a card.
mesh {
  triangle { <-0.4, 0, -0.4>, <0.4, 0, -0.4>, <0, 0.9, 0> }
  triangle { <0.4, 0, -0.4>, <0.4, 0, 0.4>, <0, 0.9, 0> }
  triangle { <0.4, 0, 0.4>, <-0.4, 0, 0.4>, <0, 0.9, 0> }
  triangle { <-0.4, 0, 0.4>, <-0.4, 0, -0.4>, <0, 0.9, 0> }
  pigment { color rgb <0.80, 0.35, 0.20> }
  rotate y*20 translate <0.3, 0, 0.4>
}
box { <-0.25, 0, -0.25>, <0.25, 0.5, 0.25> pigment { color rgb <0.25, 0.55, 0.80> } rotate y*35 translate <-0.9, 0, -0.6> }
polygon { 5, <0, 0>, <0.8, 0>, <0.8, 0.6>, <0, 0.6>, <0, 0> pigment { color rgb <0.90, 0.85, 0.35> }
  rotate y*-30 translate <0.6, 0.3, -1.4> }
box { <-0.03, 0, -0.03>, <0.03, 0.3, 0.03> pigment { color rgb 0.4 } translate <0.95, 0, -1.2> }
