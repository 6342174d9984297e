// mesh2.pov -- a mesh2 torus with smooth normals and reflection, on a
// reflective floor, lit by two lights: reflected rays and their shadows.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }

camera { location <0, 3.4, -6.5> look_at <0, 0.6, 0> angle 50 right x*4/3 }
light_source { <4, 7, -5> color rgb <0.90, 0.85, 0.80> }
light_source { <-5, 4, -1> color rgb <0.30, 0.35, 0.50> }
background { color rgb <0.12, 0.14, 0.20> }

plane { y, 0 pigment { color rgb <0.55, 0.55, 0.60> } finish { reflection 0.25 } }

#declare N = 36;   // around the ring
#declare M = 16;   // around the tube
#declare R1 = 1.3;
#declare R2 = 0.45;
mesh2 {
  vertex_vectors { N*M,
    #declare i = 0; #while (i < N) #declare j = 0; #while (j < M)
      #declare a = 2*pi*i/N; #declare b = 2*pi*j/M;
      <(R1 + R2*cos(b))*cos(a), R2*sin(b), (R1 + R2*cos(b))*sin(a)>,
    #declare j = j + 1; #end #declare i = i + 1; #end
  }
  normal_vectors { N*M,
    #declare i = 0; #while (i < N) #declare j = 0; #while (j < M)
      #declare a = 2*pi*i/N; #declare b = 2*pi*j/M;
      <cos(b)*cos(a), sin(b), cos(b)*sin(a)>,
    #declare j = j + 1; #end #declare i = i + 1; #end
  }
  face_indices { 2*N*M,
    #declare i = 0; #while (i < N) #declare j = 0; #while (j < M)
      #declare i2 = i + 1; #if (i2 = N) #declare i2 = 0; #end
      #declare j2 = j + 1; #if (j2 = M) #declare j2 = 0; #end
      <i*M + j, i2*M + j, i2*M + j2>, <i*M + j, i2*M + j2, i*M + j2>,
    #declare j = j + 1; #end #declare i = i + 1; #end
  }
  normal_indices { 2*N*M,
    #declare i = 0; #while (i < N) #declare j = 0; #while (j < M)
      #declare i2 = i + 1; #if (i2 = N) #declare i2 = 0; #end
      #declare j2 = j + 1; #if (j2 = M) #declare j2 = 0; #end
      <i*M + j, i2*M + j, i2*M + j2>, <i*M + j, i2*M + j2, i*M + j2>,
    #declare j = j + 1; #end #declare i = i + 1; #end
  }
  pigment { color rgb <0.85, 0.55, 0.20> }
  finish { ambient 0.08 diffuse 0.6 phong 0.7 phong_size 50 reflection 0.35 }
  rotate x*-30 rotate y*20
  translate y*0.95
}

// Two blocks to be seen in the torus and the floor
box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> pigment { color rgb <0.2, 0.6, 0.3> } rotate y*30 translate <-2.4, 0, 1.0> }
box { <-0.3, 0, -0.3>, <0.3, 1.4, 0.3> pigment { color rgb <0.7, 0.2, 0.2> } finish { reflection 0.2 } translate <2.3, 0, 1.4> }
