// Two surfaces, one of them in no physical surface: a hole in the section.
Point(1) = {0.2, 0, 0};  Point(2) = {0.21, 0, 0};
Point(3) = {0.21, 0, 0.01}; Point(4) = {0.2, 0, 0.01};
Point(5) = {0.22, 0, 0}; Point(6) = {0.22, 0, 0.01};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Transfinite Curve{1:7} = 2; Transfinite Surface{1, 2}; Recombine Surface{1, 2};
Physical Surface("tread") = {1};
Physical Curve("rim seat") = {4};
Physical Curve("inner surface") = {1};
Physical Curve("tread surface") = {6};
