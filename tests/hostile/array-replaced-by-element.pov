// `#declare A[1] = ...` whose right side declares A anew: the element
// being declared belongs to an array that no longer exists (its memory is
// reused by the next arrays). POV-Ray 3.7 renders this, and afterwards A
// is the new array with A[1] undefined: the value went into the old one.
// hstrace does the same, writing into no memory that is reused.
// expect: status 0
#macro Replace() #declare A = array[4]; 7 #end
#declare A = array[2];
#declare A[0] = 1;
#declare A[1] = Replace();
#if (dimension_size(A, 1) != 4)
  #error "A is not the array Replace declared"
#end
#ifdef (A[1])
  #error "the value went into the new array"
#end
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, -5>, 1 }
polygon { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> pigment { rgb 1 } }
