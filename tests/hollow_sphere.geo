// A quarter of the meridian section of a hollow sphere, inner radius 1,
// outer radius 2, for an axisymmetric body (x = r, y = z): structured
// quadrilaterals, 16 across the wall, 24 around. Physical curves: 1 = the
// inner surface, 2 = the outer surface, 3 = the equatorial plane z = 0,
// 4 = the axis r = 0.
a = 1;
b = 2;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {b, 0, 0};
Point(4) = {0, b, 0};
Point(5) = {0, a, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 17;
Transfinite Curve{2, 4} = 25;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1};
Physical Curve(4) = {3};
Physical Surface(1) = {1};
