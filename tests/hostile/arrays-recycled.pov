// Arrays made over and over (issue 22: memory flat across iterations): a
// macro's #local array of arrays on every call, and a global array
// declared anew on every pass of a loop, 100000 times each. Each array
// used to stay allocated until the parse ended, 3.8 KB a time (385 MB
// here); now an array whose symbol is given another value or goes out of
// scope is reused by the next. Under a 32 MB budget the scene parses, and
// the values show that no array was reused while still in use.
// expect: status 0
// expect: option --max-memory 32M
#macro Sum(A)
  #local V = array[16];
  #local V[3] = A;
  #local W = array[2] { V, array[3] { A, 2 * A, 3 * A } };
  #local X = W[0];
  #local Y = W[1];
  (X[3] + Y[2] + 1)
#end
#declare Total = 0;
#declare I = 0;
#while (I < 100000)
  #declare Total = Total + Sum(I);
  #declare G = array[8];
  #declare G[7] = I;
  #declare Copy = G;
  #declare G[7] = -1;
  #if (Copy[7] != I | G[7] != -1)
    #error "an array was reused while still in use"
  #end
  #declare I = I + 1;
#end
// sum of 4 I + 1 over I < 100000
#if (Total != 4 * 99999 * 100000 / 2 + 100000)
  #error concat("wrong total ", str(Total, 0, 0))
#end
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, -5>, 1 }
polygon { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> pigment { rgb 1 } }
