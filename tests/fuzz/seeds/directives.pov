// The directive language: loops, macros, arrays, strings, #switch.
#version 3.7;
#declare N = 5;
#macro Tri(I, S)
  triangle { <I, 0, 0>, <I + S, 0, 0>, <I, S, 0> pigment { rgb <I / N, 0.5, 1 - I / N> } }
#end
#declare A = array[3] { 1, 2.5, <1, 2, 3> }
#declare S = concat("a", str(N, 0, 2), chr(66), substr("hello", 2, 3), strupr("x"), vstr(3, A[2], ",", 0, 1));
#for (I, 0, N - 1)
  #switch (mod(I, 3))
    #case (0) Tri(I, 0.5) #break
    #range (1, 2) Tri(I, 0.25)
    #else #debug "never\n"
  #end
#end
#declare J = 0;
#while (J < 3)
  #if (J = 1 & strlen(S) > 2) #local K = J * 2; #elseif (J > 1) #declare K = -1; #else #declare K = 0; #end
  #declare J = J + 1;
#end
#ifdef (K) #undef K #end
#ifndef (K) #declare K = dimension_size(A, 1) + dimensions(A); #end
camera { location <2, 1, -5> look_at <2, 0.5, 0> angle 60 }
light_source { <0, 5, -5>, 1 spotlight point_at 0 radius 20 falloff 30 tightness 5 }
