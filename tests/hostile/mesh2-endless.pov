// A mutation left a mesh2's vertex loop without its increment (issue 22:
// 58-108 s): the budget stops it, naming the loop.
// expect: status 2
// expect: error mesh2-endless.pov:11:5: more than 20000000 tokens read again by loops and macro calls (--max-repeated-tokens): is the #while at mesh2-endless.pov:8 endless?
mesh2 {
  vertex_vectors { 50000000,
    #declare I = 0;
    #while (I < 10)
      <I, 0, 0>,
      #declare I = I;
    #end
  }
  face_indices { 1, <0, 1, 2> }
}
