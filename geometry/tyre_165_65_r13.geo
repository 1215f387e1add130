// GreenTread tyre section: the 165/65 R13 of Table A.3, layered as Table A.4.
//
// The section lies in the (x, z) plane: x is the radius, z the axial
// coordinate (the tyre axis is the z-axis). GreenTread revolves it about the
// z-axis by 2 pi / N into one periodic cell. Units: metres.
//
// Every dimension is an ONELAB parameter ("Parameters/..."): GreenTread sets
// them from subsection Geometry of the scene before it opens this file; the
// values below are the defaults when the file is opened by hand in gmsh.
//
// A new design is a new .geo file. It must define:
//  - Physical Surface "tread", "belt", "sidewall", "bead": the materials;
//  - Physical Curve "rim seat", "inner surface", "tread surface": the outer
//    boundaries that carry conditions. Interior interfaces stay untagged.
//  - transfinite, recombined (quadrilateral) surfaces.
//
// The blocks, all quadrilaterals with straight edges (so that Pappus gives
// each layer's volume exactly) unless 'Crown drop' curves the tread surface:
//  - tread pattern and belt: across the crown, each split into a centre and
//    two shoulders, the shoulders as wide as the sidewall is thick;
//  - each sidewall: an upper block from under the belt shoulder down to the
//    bulge (the widest point of the section), and a lower block from the
//    bulge to the bead, tapering from the sidewall to the bead width;
//  - each bead: a rectangle on the rim seat.

DefineConstant[
  rim_diameter       = {0.3302,  Name "Parameters/Rim diameter"},
  section_height     = {0.10725, Name "Parameters/Section height"},
  tread_width        = {0.165,   Name "Parameters/Tread width"},
  section_width      = {0.175,   Name "Parameters/Section width"},
  rim_width          = {0.1143,  Name "Parameters/Rim width"},
  tread_thickness    = {0.008,   Name "Parameters/Tread thickness"},
  belt_thickness     = {0.006,   Name "Parameters/Belt thickness"},
  sidewall_thickness = {0.006,   Name "Parameters/Sidewall thickness"},
  bead_width         = {0.008,   Name "Parameters/Bead width"},
  bead_height        = {0.008,   Name "Parameters/Bead height"},
  bulge_height       = {0.5,     Name "Parameters/Bulge height"},
  mesh_size          = {0.008,   Name "Parameters/Mesh size"},
  // Not in subsection Geometry: set it with
  //   Geometry/Other constants = Crown drop=0.003
  // The tread surface becomes a circular arc that falls by this much from
  // the centre to the edge of the tread (0: flat).
  crown_drop         = {0,       Name "Parameters/Crown drop"},
  // Also through 'Other constants' (Crown refinement=2): the crown's
  // elements across the tread and through the tread pattern are this many
  // times smaller than 'Mesh size'; the rest of the section keeps it, so
  // halving 'Mesh size' still halves every element.
  crown_refinement   = {1,       Name "Parameters/Crown refinement"}
];

If (crown_refinement < 1 || crown_refinement > 8)
  Error("parameter 'Parameters/Crown refinement' = %g is not allowed; allowed: [1, 8]", crown_refinement);
EndIf
If (crown_drop < 0 || crown_drop >= tread_thickness)
  Error("parameter 'Parameters/Crown drop' = %g is not allowed; allowed: [0, 'Tread thickness' = %g)", crown_drop, tread_thickness);
EndIf

R_rim  = rim_diameter / 2;
R_out  = R_rim + section_height;        // tread surface
R_belt = R_out - tread_thickness;       // tread / belt interface
R_in   = R_belt - belt_thickness;       // belt underside, inner surface
z_t    = tread_width / 2;
z_s    = z_t - sidewall_thickness;      // inner edge of the shoulders
z_r    = rim_width / 2;
R_bead = R_rim + bead_height;
R_mid  = R_bead + bulge_height * (R_in - R_bead);
z_out  = section_width / 2;
z_in   = z_out - sidewall_thickness;

// Crown points: rows at R_out, R_belt, R_in; columns -z_t, -z_s, z_s, z_t.
rows[] = {R_out, R_belt, R_in};
cols[] = {-z_t, -z_s, z_s, z_t};
For i In {0:2}
  For j In {0:3}
    x = rows[i];
    If (i == 0 && crown_drop > 0)
      // On the arc of radius R_c through (R_out, 0) and (R_out - drop, z_t).
      R_c = (z_t^2 + crown_drop^2) / (2 * crown_drop);
      x = R_out - R_c + Sqrt(R_c^2 - cols[j]^2);
    EndIf
    c[4 * i + j] = newp; Point(c[4 * i + j]) = {x, 0, cols[j]};
  EndFor
EndFor
If (crown_drop > 0)
  crown_centre = newp; Point(crown_centre) = {R_out - R_c, 0, 0};
EndIf

// Sidewall and bead points, side s = 0 (z < 0) and 1 (z > 0).
For s In {0:1}
  sign = 2 * s - 1;
  m_in[s]  = newp; Point(m_in[s])  = {R_mid,  0, sign * z_in};
  m_out[s] = newp; Point(m_out[s]) = {R_mid,  0, sign * z_out};
  b_in[s]  = newp; Point(b_in[s])  = {R_bead, 0, sign * (z_r - bead_width)};
  b_out[s] = newp; Point(b_out[s]) = {R_bead, 0, sign * z_r};
  r_in[s]  = newp; Point(r_in[s])  = {R_rim,  0, sign * (z_r - bead_width)};
  r_out[s] = newp; Point(r_out[s]) = {R_rim,  0, sign * z_r};
EndFor

// Node counts: one per direction, shared by opposite edges of every block.
n_center = Ceil(2 * z_s * crown_refinement / mesh_size) + 1;
n_side   = Ceil(sidewall_thickness / mesh_size) + 1;
n_tread  = Ceil(tread_thickness * crown_refinement / mesh_size) + 1;
n_belt   = Ceil(belt_thickness / mesh_size) + 1;
n_upper  = Ceil(Sqrt((R_in - R_mid)^2 + (z_in - z_s)^2) / mesh_size) + 1;
n_lower  = Ceil(Sqrt((R_mid - R_bead)^2 + (z_r - bead_width - z_in)^2) / mesh_size) + 1;
n_bead   = Ceil(bead_height / mesh_size) + 1;

// Crown: horizontal lines h[i][j] from column j to j+1 on row i; vertical
// lines v[i][j] from row i to row i+1 at column j.
For i In {0:2}
  For j In {0:2}
    h[3 * i + j] = newl;
    If (i == 0 && crown_drop > 0)
      Circle(h[3 * i + j]) = {c[4 * i + j], crown_centre, c[4 * i + j + 1]};
    Else
      Line(h[3 * i + j]) = {c[4 * i + j], c[4 * i + j + 1]};
    EndIf
    Transfinite Curve{h[3 * i + j]} = (j == 1) ? n_center : n_side;
  EndFor
EndFor
For i In {0:1}
  For j In {0:3}
    v[4 * i + j] = newl; Line(v[4 * i + j]) = {c[4 * i + j], c[4 * (i + 1) + j]};
    Transfinite Curve{v[4 * i + j]} = (i == 0) ? n_tread : n_belt;
  EndFor
EndFor
For i In {0:1}
  For j In {0:2}
    loop = newll; Curve Loop(loop) = {h[3 * i + j], v[4 * i + j + 1], -h[3 * (i + 1) + j], -v[4 * i + j]};
    crown[3 * i + j] = news; Plane Surface(crown[3 * i + j]) = {loop};
  EndFor
EndFor

// Sidewalls and beads. The shoulder under the belt: h[6] (left), h[8] (right).
shoulder_inner[] = {c[9], c[10]};   // at -z_s and z_s on the R_in row
shoulder_outer[] = {c[8], c[11]};   // at -z_t and z_t
shoulder_line[]  = {h[6], h[8]};
For s In {0:1}
  upper_in[s]  = newl; Line(upper_in[s])  = {shoulder_inner[s], m_in[s]};
  upper_out[s] = newl; Line(upper_out[s]) = {shoulder_outer[s], m_out[s]};
  bulge[s]     = newl; Line(bulge[s])     = {m_in[s], m_out[s]};
  lower_in[s]  = newl; Line(lower_in[s])  = {m_in[s], b_in[s]};
  lower_out[s] = newl; Line(lower_out[s]) = {m_out[s], b_out[s]};
  bead_top[s]  = newl; Line(bead_top[s])  = {b_in[s], b_out[s]};
  bead_inner[s]= newl; Line(bead_inner[s])= {b_in[s], r_in[s]};
  bead_outer[s]= newl; Line(bead_outer[s])= {b_out[s], r_out[s]};
  seat[s]      = newl; Line(seat[s])      = {r_in[s], r_out[s]};
  Transfinite Curve{upper_in[s], upper_out[s]} = n_upper;
  Transfinite Curve{lower_in[s], lower_out[s]} = n_lower;
  Transfinite Curve{bulge[s], bead_top[s], seat[s]} = n_side;
  Transfinite Curve{bead_inner[s], bead_outer[s]} = n_bead;

  // Around the upper block: shoulder inner -> shoulder outer -> bulge outer
  // -> bulge inner. The shoulder line runs outer to inner on the left and
  // inner to outer on the right.
  loop = newll;
  If (s == 0)
    Curve Loop(loop) = {-shoulder_line[s], upper_out[s], -bulge[s], -upper_in[s]};
  Else
    Curve Loop(loop) = {shoulder_line[s], upper_out[s], -bulge[s], -upper_in[s]};
  EndIf
  upper[s] = news; Plane Surface(upper[s]) = {loop};
  loop = newll; Curve Loop(loop) = {bulge[s], lower_out[s], -bead_top[s], -lower_in[s]};
  lower[s] = news; Plane Surface(lower[s]) = {loop};
  loop = newll; Curve Loop(loop) = {bead_top[s], bead_outer[s], -seat[s], -bead_inner[s]};
  bead[s] = news; Plane Surface(bead[s]) = {loop};
EndFor

all[] = {crown[], upper[], lower[], bead[]};
Transfinite Surface{all[]};
Recombine Surface{all[]};

Physical Surface("tread")    = {crown[0], crown[1], crown[2]};
Physical Surface("belt")     = {crown[3], crown[4], crown[5]};
Physical Surface("sidewall") = {upper[], lower[]};
Physical Surface("bead")     = {bead[]};
Physical Curve("rim seat")      = {seat[]};
Physical Curve("inner surface") = {h[7], upper_in[], lower_in[], bead_inner[]};
Physical Curve("tread surface") = {h[0], h[1], h[2]};
