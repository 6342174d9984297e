// charset utf8: the Unicode character map (platform 3 before Macintosh's),
// characters read from UTF-8 (Times' "£©™‰", Cyrvetica's letters at
// U+00C0..U+00FF), a tab escape and a character the font lacks (glyph 0)
#version 3.7;
global_settings { assumed_gamma 1 charset utf8 }
camera { location <1.8, 0.4, -4> look_at <1.8, 0.4, 0> }
light_source { <-3, 5, -6> color rgb 1 }
plane { z, 0.5 pigment { rgb 0.8 } }
text { ttf "timrom.ttf" "«£©» “™” ‰\tü" 0.2, 0 pigment { rgb <0.9, 0.7, 0.1> } translate <-0.3, 0.6, 0> }
text { ttf "cyrvetic.ttf" "ÀÁÂÃÄÅ ÿ" 0.2, 0 pigment { rgb <0.3, 0.7, 0.9> } translate <-0.3, -0.5, 0> }
