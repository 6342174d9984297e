// The same union of a million boxes with all the memory it wants: the
// world's build is held to --max-parse-seconds too, the parse's time and
// the build's together (it ran for 14 s before, unbounded by any option).
// expect: status 2
// expect: option --max-memory 1T --max-parse-seconds 1
// expect: error union-doublings-time.pov:13:1: building the world from the scene took more than the 1 s of --max-parse-seconds (the parse and the build together), in this object
#declare U = union { box { 0, 1 } }
#declare I = 0;
#while (I < 20)
  #declare U = union { object { U } object { U translate x } }
  #declare I = I + 1;
#end
object { U pigment { rgb 1 } }
