// Normals averaging two copies of the one before, 40 deep: 41 normals,
// 2^40 paths. The parse's report of approximations walked them all (a hang
// under any option); it now visits each normal once. The render then
// takes hours, as POV-Ray's does: each normal now counts towards
// --max-render-seconds, which stops it.
// expect: status 2
// expect: option --max-render-seconds 1
camera { location <0, 0, -3> look_at 0 }
light_source { <0, 0, -3>, 1 }
#declare N = normal { bumps 1 }
#for (I, 1, 40)
  #declare N = normal { average normal_map { [1 N] [1 N] } }
#end
plane { z, 0 pigment { rgb 1 } normal { N } }
