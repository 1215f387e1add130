// A section with boundaries but no physical surface (no material).
Point(1) = {0.2, 0, 0}; Point(2) = {0.25, 0, 0}; Point(3) = {0.25, 0, 0.05}; Point(4) = {0.2, 0, 0.05};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Surface{1}; Recombine Surface{1};
Physical Curve("rim seat") = {1}; Physical Curve("inner surface") = {4}; Physical Curve("tread surface") = {2};
