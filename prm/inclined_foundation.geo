// A block on an inclined foundation: the parallelogram with
// corners (0,0), (1,0.25), (1,0.75), (0,0.5), i.e. the paper's block sheared
// so that Gamma_3 rises at 14 degrees. Physical ids are the boundary ids of
// the .prm: 1 clamped (x = 0), 2 contact (the inclined base), 3 loaded top,
// 4 free (x = 1). Structured quadrilaterals, 16 x 8.
// Regenerate with: gmsh -2 -format msh22 inclined_foundation.geo
Point(1) = {0, 0, 0};
Point(2) = {1, 0.25, 0};
Point(3) = {1, 0.75, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 17;
Transfinite Curve{2, 4} = 9;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {4};
Physical Curve(4) = {2};
Physical Curve(2) = {1};
Physical Curve(3) = {3};
Physical Surface(10) = {1};
