// The force of the fluid on whatever lies inside a rectangle, from the fluid alone: a control-volume
// momentum balance that does not use the immersed-boundary forcing, so that it checks the forcing's
// reaction (body_NNN/force_x, force_y, docs/output.md). For a control volume CV with outward normal n,
// per unit depth, the force of the fluid on the body inside it is
//   F = -rho [ d/dt int_CV u dA + oint u (u.n) ds ] + oint ( -rho p n + rho nu (grad u + grad u^T).n ) ds
// with p the kinematic pressure (p / rho_f). Any other source of momentum inside the rectangle
// (another body's forcing) is counted as part of the body.
//
// Discretisation on the collocated grid (core/fields.hpp), the rectangle made of whole cells:
//  - momentum: sum of the cell velocities times the cell area;
//  - momentum flux: the face velocity (divergence-free after the projection) times the mean of the
//    two cell values beside the face, the central flux of the solver's convection (fluid/operators.hpp);
//  - pressure: the mean of the two cell pressures beside the face (what the wide centre gradient
//    telescopes to);
//  - viscous traction: the normal derivatives across the face by the compact difference of the two
//    cells beside it (what the compact Laplacian telescopes to), the tangential derivative of the
//    transposed part by the mean of the two cells' central differences.
// Each term is second order in space. In time the balance of the step t^n -> t^{n+1} is centred at
// t^{n+1/2}: (M^{n+1} - M^n)/dt, the mean of the flux and viscous integrals at t^n and t^{n+1} (second
// order), and the pressure p^{n+1} of the step alone (the solver's incremental projection makes
// p^{n+1} the pressure that acted over the step, an approximation of p(t^{n+1/2}) first order in
// time: the pressure term carries the solver pressure's own time error).
// The rectangle must lie one cell or more inside the box: the sides read the cells on both sides
// and, for the tangential derivatives, their neighbours along the side; ghost cells are not read.
#pragma once
#include <array>
#include <vector>

#include "core/fields.hpp"
#include "core/grid.hpp"

namespace ibms {

using ForceVector = std::array<double, 2>;

// Cells [i_begin, i_end) x [j_begin, j_end); the sides are the faces x_face(i_begin),
// x_face(i_end), y_face(j_begin), y_face(j_end).
struct CellRectangle {
  int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;
  bool operator==(const CellRectangle&) const = default;
};

// The control volume of a body with bounding box [lower, upper] and diameter D: the box widened by
// max(D/2, 6 h) on every side (h = dx or dy), out to the next cell faces, then clipped so that it
// keeps at least 2 cells from every side of the domain (periodic sides included: it does not wrap).
// D/2 puts the sides where the near field has decayed (a CV shrunk to the kernel's support would
// sample the diffuse interface), 6 h keeps them 6 h - 2 h = 4 h clear of the widest kernel's support
// (peskin4, 2 h) on coarse grids; 2 cells from the domain's sides keep the neighbours the sides read
// inside the box. Throws std::invalid_argument if the grid has fewer than 5 cells in a direction.
CellRectangle control_volume_around(const Grid& grid, const ForceVector& lower, const ForceVector& upper,
                                    double diameter);

// Smallest distance between the bounding box [lower, upper] and the sides of the rectangle
// (negative when the box reaches out of it) [length]. The balance gives the body's force only
// when this exceeds the half-width of the forcing's kernel (2 h at most), e.g. not once the
// rectangle is clipped next to a wall the body approaches.
double control_volume_clearance(const Grid& grid, const CellRectangle& rectangle, const ForceVector& lower,
                                const ForceVector& upper);

// The fluid fields at one time level: cell velocities, face velocities, kinematic pressure p / rho_f.
struct FlowFields {
  const CellField& velocity_x;
  const CellField& velocity_y;
  const FaceField& velocity_face_x;
  const FaceField& velocity_face_y;
  const CellField& pressure;
};

// The integrals of the balance at one time level, per unit density and depth.
struct ControlVolumeTerms {
  ForceVector momentum{0.0, 0.0};       // int_CV u dA [length^3/time]
  ForceVector momentum_flux{0.0, 0.0};  // oint u (u.n) ds [length^3/time^2]
  ForceVector pressure{0.0, 0.0};       // -oint p n ds [length^3/time^2]
  ForceVector viscous{0.0, 0.0};        // oint nu (grad u).n ds, the part the compact Laplacian
                                        // telescopes to [length^3/time^2]
  ForceVector viscous_transpose{0.0, 0.0};  // oint nu (grad u^T).n ds: zero for a divergence-free
                                            // field in the continuum, O(h^2) here [length^3/time^2]
};

// The terms on `rectangle`; throws std::invalid_argument if it is empty or less than one cell
// inside the box.
ControlVolumeTerms control_volume_terms(const Grid& grid, const CellRectangle& rectangle, const FlowFields& fields,
                                       double kinematic_viscosity);

// The force of the fluid on the body over the step of length dt from the terms at t^n (`before`)
// and t^{n+1} (`after`) on the same rectangle, time-centred as in the header:
//   F = rho [ -(M^{n+1} - M^n)/dt - (Phi^n + Phi^{n+1})/2 + P^{n+1} + (V^n + V^{n+1})/2 ] [force/length],
// V = viscous + viscous_transpose.
ForceVector control_volume_force(const ControlVolumeTerms& before, const ControlVolumeTerms& after, double dt,
                                 double density);

// The same in one call from the fields at t^n and t^{n+1}.
ForceVector control_volume_force(const Grid& grid, const CellRectangle& rectangle, const FlowFields& before,
                                 const FlowFields& after, double kinematic_viscosity, double density, double dt);

// A force history from the immersed boundary beside the control-volume one, one row per step
// (series_every = 1 for a time mean), and their relative difference cv / ib - 1.
struct DragAgreement {
  double immersed_boundary = 0.0;
  double control_volume = 0.0;
  double relative_difference = 0.0;
};
// Final values (a steady run): the last row.
DragAgreement final_drag_agreement(const std::vector<double>& immersed_boundary,
                                   const std::vector<double>& control_volume);
// Time means over the rows with time >= t_from: each row is the force of the step that ends at its
// time, weighted by that step's length time[k] - time[k-1] (the exact mean of the step forces when
// every step is written). Throws std::invalid_argument with fewer than two rows in the window.
DragAgreement mean_drag_agreement(const std::vector<double>& time, const std::vector<double>& immersed_boundary,
                                  const std::vector<double>& control_volume, double t_from);

}  // namespace ibms
