// A tiny mixed mesh for the volume mesh readers' tests (test_volume_mesh_io):
// a hexahedron and a prism (an extruded quadrangle and triangle), and a
// tetrahedral region above them, with a pyramid where its tetrahedra meet the
// hexahedron's top quadrangle. Physical volumes 3 (the hexahedron) and 7.
lc = 2;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc}; Point(5) = {2, 0, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -2}; Plane Surface(2) = {2};
Transfinite Curve{1:6} = 2;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 0.5} { Surface{1, 2}; Layers{1}; Recombine; };
// the top points 6 (0,0) 7 (1,0) 11 (1,1) 15 (0,1) 17 (2,0) at z = 0.5, and the top
// curves 8 (6-7) 9 (7-11) 10 (11-15) 11 (15-6) 30 (7-17) 31 (17-11)
Point(100) = {0.8, 0.4, 1.3, lc};
Line(101) = {6, 100}; Line(102) = {7, 100}; Line(103) = {11, 100};
Line(104) = {15, 100}; Line(105) = {17, 100};
Curve Loop(111) = {8, 102, -101}; Plane Surface(111) = {111};
Curve Loop(112) = {30, 105, -102}; Plane Surface(112) = {112};
Curve Loop(113) = {31, 103, -105}; Plane Surface(113) = {113};
Curve Loop(114) = {10, 104, -103}; Plane Surface(114) = {114};
Curve Loop(115) = {11, 101, -104}; Plane Surface(115) = {115};
Surface Loop(120) = {out[0], out[6], 111, 112, 113, 114, 115};
Volume(121) = {120};
Physical Volume(3) = {out[1]};
Physical Volume(7) = {out[7], 121};
