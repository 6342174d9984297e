// A #version of 2.2e45 (found by the scene fuzzer in this issue's second
// campaign): the gamma rules and the noise generator compared it as an int,
// a conversion undefined beyond int's range. POV-Ray takes any version;
// hstrace compares it as a double and renders.
// expect: status 0
#version 2222222222222222222222222222222222222222222223.7;
camera { location <0, 0, -2> look_at 0 }
light_source { <1, 2, -3>, 1 }
triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> pigment { bozo } }
