// The half cylinder of meshes/half_cylinder.geo with its centre at the
// origin (contact point (0, -R)): tests/curved_zone_measures.sh measures
// the same contact at two origins. Physical curves: 11 = the arc, 12 = top.
R = 5;
Point(1) = {0, 0, 0, 1};
Point(2) = {-R, 0, 0, 1};
Point(3) = {0, -R, 0, 1};
Point(4) = {R, 0, 0, 1};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(11) = {1, 2};
Physical Curve(12) = {3};
Physical Surface(1) = {1};

// Fine near the contact point, coarse far away.
Field[1] = Distance;
Field[1].PointsList = {3};
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
