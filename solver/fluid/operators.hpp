// Second-order finite-volume operators on the collocated grid (docs/method.md §2.2). Cell inputs
// must have their ghost layer filled (fluid/boundary_conditions.hpp); outputs are interior only.
// Face fields: x-faces (nx+1) x ny, y-faces nx x (ny+1) (core/fields.hpp).
#pragma once
#include "core/fields.hpp"
#include "core/grid.hpp"

namespace ibms {

// Compact 5-point Laplacian L_c q = D G_f q [q/length^2].
void laplacian(const Grid& grid, const CellField& q, CellField& out);

// Conservative convection with the face velocities: div(U_f q) with q interpolated to faces by
// the arithmetic mean (central, docs/method.md §2.2) [q/time].
void convection(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                const CellField& q, CellField& out);

// The same with upwind-biased face values of the kappa family (van Leer 1985), by the sign of the
// face velocity: q_f = q_up + (1 - kappa)/4 (q_up - q_upup) + (1 + kappa)/4 (q_down - q_up);
// kappa = 1/2 is QUICK (Leonard 1979, (6 q_up + 3 q_down - q_upup) / 8), kappa = 0 Fromm's scheme
// (q_up + (q_down - q_upup) / 4). Where the second upwind cell lies beyond the ghost layer (next to a
// wall) the central mean. Periodic directions wrap. FluidSchemes::convection.
void convection_upwind_biased(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                              const CellField& q, CellField& out, double kappa);

// Wide cell-centre gradient G_c p = ((p_{i+1} - p_{i-1})/(2 dx), (p_{j+1} - p_{j-1})/(2 dy)).
void centre_gradient(const Grid& grid, const CellField& p, CellField& grad_x, CellField& grad_y);

// Face divergence D U = (U_{i+1/2} - U_{i-1/2})/dx + (V_{j+1/2} - V_{j-1/2})/dy, into a
// contiguous (ny, nx) buffer scaled by `scale`.
void divergence(const Grid& grid, const FaceField& velocity_face_x, const FaceField& velocity_face_y,
                double scale, double* out);

// max over cells of |D U| [1/time].
double max_abs_divergence(const Grid& grid, const FaceField& velocity_face_x,
                          const FaceField& velocity_face_y);

// Vorticity dv/dx - du/dy by central differences of the ghost-filled cell velocities [1/time].
void vorticity(const Grid& grid, const CellField& velocity_x, const CellField& velocity_y, CellField& out);

}  // namespace ibms
