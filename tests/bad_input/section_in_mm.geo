// A section drawn in millimetres: its coordinates are 1000 times a tyre's in metres.
Point(1) = {200, 0, 0}; Point(2) = {250, 0, 0}; Point(3) = {250, 0, 50}; Point(4) = {200, 0, 50};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("tread") = {1};
Physical Curve("rim seat") = {1}; Physical Curve("inner surface") = {4}; Physical Curve("tread surface") = {2};
