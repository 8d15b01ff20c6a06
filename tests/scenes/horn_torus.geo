// A meridian section that meets the axis at one point: the disk of radius
// 0.5 about (0.5, 0), a horn torus when revolved (tests/self_checks.cc).
// Physical curves: 1 = the half circle x >= 0.5, 2 = the half circle
// x <= 0.5 (through the axis point (0, 0)).
h = 0.08;
Point(1) = {0.5, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {0.5, 0.5, 0, h};
Point(4) = {0, 0, 0, h / 4};
Point(5) = {0.5, -0.5, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(1) = {4, 1};
Physical Curve(2) = {2, 3};
Physical Surface(1) = {1};
