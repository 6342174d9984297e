// A union holding a copy of itself, again and again: the nesting grows
// without any nesting in the text, and every walk of the tree recursed
// through it (a stack overflow, status 139, before).
// expect: status 2
// expect: error union-copies.pov:9:16: nested too deeply (unions inside unions more than 200 levels)
#declare U = union { triangle { 0, x, y } }
#declare I = 0;
#while (I < 100000)
  #declare U = union { object { U } }
  #declare I = I + 1;
#end
object { U pigment { rgb 1 } }
