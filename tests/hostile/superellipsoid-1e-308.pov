// Exponents positive but so small that 2/e is infinite: the message said
// "both must be positive", which they are; it says what is wrong instead.
// expect: status 2
// expect: error superellipsoid-1e-308.pov:6:18: superellipsoid exponents <1e-308, 1e-308>: too small (2 divided by each must be a finite number)
camera { location <0, 1, -5> look_at 0 }
superellipsoid { <1e-308, 1e-308> pigment { rgb 1 } }
