// The lower hemisphere of Code_Aster's SSNV104 as a meridian section
// (axisymmetric: x = r, y = z): a quarter disc of radius R = 50 mm, centre
// (0, -50), touching the other hemisphere at the origin. Triangles
// graded toward the contact point (0.25 mm there, 5 mm far away).
// Physical curves: 11 = the arc (possible contact zone), 12 = the equator
// plane (where the hemisphere is pushed), 13 = the axis r = 0.
R = 50;
Point(1) = {0, -1 * R, 0, 1};
Point(2) = {0, 0, 0, 1};
Point(3) = {R, -1 * R, 0, 1};
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(11) = {1};
Physical Curve(12) = {2};
Physical Curve(13) = {3};
Physical Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.25;
Field[2].SizeMax = 5;
Field[2].DistMin = 12;
Field[2].DistMax = 40;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
