// `hierarchy` belongs to height fields, meshes, blobs and CSG, as in POV-Ray
// (Not_With): on a box it is an error at the keyword, not ignored.
// expect: status 2
// expect: error hierarchy-on-a-box.pov:7:12: Keyword 'hierarchy' cannot be used with this object (height fields, meshes, blobs and CSG take it).
camera { location <0, 2, -3> look_at <0, 0, 0> }
union { box { 0, 1 } box { 2, 3 } hierarchy off }
box { 0, 1 hierarchy off }
