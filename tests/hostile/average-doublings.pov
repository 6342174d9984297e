// Averages of two copies of the one before, 40 deep: 41 pigments, but
// 2^40 colours at every point. The world's build walked all the paths to
// ask whether the pigment is opaque (a hang, under any option); now it
// visits each pigment once. The render then takes hours, as POV-Ray's does;
// --max-render-seconds, checked between rays, came only after them: the
// colours now count towards it too, and it stops the render.
// expect: status 2
// expect: option --max-render-seconds 1
camera { location <0, 0, -3> look_at 0 }
#declare P = pigment { bozo }
#for (I, 1, 40)
  #declare P = pigment { average pigment_map { [1 P] [1 P] } }
#end
plane { z, 0 pigment { P } finish { ambient 1 } }
