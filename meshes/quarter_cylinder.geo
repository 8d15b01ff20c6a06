// Lower right quarter of a cylinder of radius R (centre (0, R)) touching the
// line x2 = 0 at the origin: the half model of meshes/half_cylinder.geo,
// cut on its symmetry line x1 = 0. Triangles graded toward the contact
// point. Physical curves: 11 = the arc (possible contact zone), 12 = the
// flat top, 13 = the symmetry line.
R = 5;
Point(1) = {0, R, 0, 1};
Point(2) = {0, 0, 0, 1};
Point(3) = {R, R, 0, 1};
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(11) = {1};
Physical Curve(12) = {2};
Physical Curve(13) = {3};
Physical Surface(1) = {1};

// Fine near the contact point, coarse far away.
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.03;
Field[2].SizeMax = 0.8;
Field[2].DistMin = 0.6;
Field[2].DistMax = 4;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
