// A union of two copies of itself, twenty times over (issue 39): 189
// bytes, a million boxes, 6 million polygons. The world's build took 3.2
// GB and 14 s, past --max-memory, which bounded the parse alone; now the
// polygons a flattening will make are counted from the scene's tree first
// (once per shared union), and the object that takes the world past the
// budget is refused before anything is made.
// expect: status 2
// expect: option --max-memory 256M
// expect: error union-doublings.pov:16:1: the world built from the scene would take 3.2 GiB (6291456 polygons) with this object, more than the memory budget of 256 MiB (--max-memory sets it)
#declare U = union { box { 0, 1 } }
#declare I = 0;
#while (I < 20)
  #declare U = union { object { U } object { U translate x } }
  #declare I = I + 1;
#end
object { U pigment { rgb 1 } }
