// A square plate (-3, 3)^2 with a hole of radius 1 about the origin
// (tests/pin_in_hole.prm). Physical curves: 3 = the hole, 4 = the outer
// sides.
R = 1;
L = 3;
h = 0.05;
H = 0.6;
Point(1) = {0, 0, 0, h};
Point(2) = {R, 0, 0, h};
Point(3) = {0, R, 0, h};
Point(4) = {-R, 0, 0, h};
Point(5) = {0, -R, 0, h};
Point(6) = {-L, -L, 0, H};
Point(7) = {L, -L, 0, H};
Point(8) = {L, L, 0, H};
Point(9) = {-L, L, 0, H};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {8, 9};
Line(8) = {9, 6};
Curve Loop(1) = {5, 6, 7, 8};
Curve Loop(2) = {1, 2, 3, 4};
Plane Surface(1) = {1, 2};
Physical Curve(3) = {1, 2, 3, 4};
Physical Curve(4) = {5, 6, 7, 8};
Physical Surface(1) = {1};
