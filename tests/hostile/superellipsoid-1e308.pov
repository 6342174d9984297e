// A superellipsoid of exponents 1e308: 1/e (5e307) was converted to an
// int (UBSan: outside the range of int). POV-Ray renders it.
// expect: status 0
camera { location <0, 1, -5> look_at 0 }
light_source { <2, 4, -3>, 1 }
superellipsoid { <1e308, 1e308> pigment { rgb 1 } }
