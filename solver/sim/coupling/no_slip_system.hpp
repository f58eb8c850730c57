// The marker system of the end-of-step constraint, ibm.coupling = "no_slip" (docs/method.md
// §3.7; the coupling object is sim/coupling/end_of_step_constraint.hpp): the immersed-boundary
// forces as the Lagrange multipliers of the no-slip constraint at the end of the step (Taira &
// Colonius 2007). After the
// projection, the marker force corrections dF solve
//     J P_0 S (dt dF) = U_target - J u^{n+1},
// S spreading onto the cells and the faces (the balanced momentum interpolation of FaceForcing), P_0
// the homogeneous projection, and J either the interpolation of the cell velocities u^{n+1}
// (ibm.constrained_velocity = "cells") or J_f of the face velocities U_f^{n+1} ("faces":
// interpolate_faces, the discretely divergence-free field that carries mass and momentum; on a
// staggered grid, as in Taira & Colonius, it is the velocity itself). The two differ by the
// momentum interpolation's dt (mean(G_c) - G_f) p (§2.3): the other one's slip is measured, not
// held. The pressure takes the gradient part of the force. The system is small (two unknowns per
// marker) and solved by GMRES with restarts (Saad & Schultz 1986), one Poisson solve per product (a
// cycle's correction is projected with its products' potentials, without a solve of its own); the unknowns of each body are
// scaled by its reference speed, preconditioned on the right by the system without its projection
// (MarkerPreconditioner, J S per body; the residual stays the true one), and the iteration stops when the largest slip of any marker is
// below the tolerance (a maximum norm, checked on the true residual of the marker system), or when
// a restart cycle has not halved it (the floor of the marker system, docs/method.md §3.7).
// cells_from_faces: the cells take the mean of the face increments (A S_f, under "faces") in place
// of the kernel spread S.
// Bodies that respond (mass-spring, body_velocity_change not empty): the target is the rim velocity
// at the end of the step, which the force itself changes through the body's linearised response R,
// so the corrections solve (J P_0 S + R rho_f dV) (dt dF) = r: the fluid and the rim's inertia and
// springs together in one marker system (docs/method.md §3.7).
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "fluid/fluid_solver.hpp"
#include "ibm/delta_kernel.hpp"
#include "ibm/ib_operators.hpp"
#include "sim/coupling/body_coupling.hpp"
#include "sim/coupling/marker_preconditioner.hpp"
#include "solid/implicit_euler.hpp"

namespace ibms {

// Storage of the marker-space GMRES, reserved once for the largest marker count.
struct NoSlipWorkspace {
  static constexpr int restart = 40;  // Krylov vectors per cycle
  std::vector<double> basis;          // V: (restart + 1) vectors of n
  std::vector<double> images;         // A V: restart vectors of n
  std::vector<double> hessenberg;     // (restart + 1) x restart, column-major
  std::vector<double> cosine, sine, rotated, coefficients;
  std::vector<double> rhs, solution, residual;
  std::vector<double> preconditioned;  // M^-1 of a Krylov vector (right preconditioning)
  // The Poisson potentials phi_j of the first products of a cycle (the projection of M^-1 v_j), and
  // in the last field their combination sum_j y_j phi_j: the potential of the cycle's correction,
  // applied without another Poisson solve (the projection is linear). A cycle that takes more
  // products than this holds projects its correction with a solve. Empty: always a solve.
  static constexpr int kept_potentials = 6;
  std::vector<CellField> potentials;
  void reserve(std::size_t max_unknowns);
  void reserve_potentials(const Grid& grid) { potentials.assign(kept_potentials + 1, CellField(grid)); }
};

// What the coupling keeps between its calls, allocated once when the Simulation is built.
struct NoSlipArrays {
  // The projected increment of one correction.
  CellField slip_increment_x, slip_increment_y;
  // The step's force dt S F on the cells and dt S_f F on the faces (the balanced momentum
  // interpolation, FaceForcing); after the projection the faces are the scratch of the
  // corrections' face increments.
  CellField force_cell_x, force_cell_y;
  FaceField force_face_x, force_face_y;
  NoSlipWorkspace work;
  MarkerPreconditioner preconditioner;
  // Per body, the linearised response of a mass-spring body over the fluid step,
  // (M + dt D + dt^2 S) factorised at the step's start (docs/method.md §3.7).
  std::vector<ImplicitSpringSystem> response_systems;
};


struct NoSlipResult {
  int products = 0;      // J P_0 S products (one Poisson solve each)
  double max_change = 0; // sum over corrections of max |P_0 g|, a bound on the change of u^{n+1} [length/time]
};

// Corrects forcing_sum and the level n+1 fields of `state` until the slip of every body is at most
// tolerance (in units of its slip_reference_speed), a cycle stagnates or max_products products were spent; leaves
// the slip of the constrained velocity (slip_max, slip_rms or face_slip_max, face_slip_rms).
// on_faces: constrain J_f U_f^{n+1} instead of J u^{n+1}. walls: the wall speeds at t^{n+1}.
// Each body's face_stencils must be mapped at its markers (map_face_stencils; the markers stay put
// over the solve, so they are mapped once, not per product).
NoSlipResult hold_no_slip(const Grid& grid, KernelKind kernel, const WallVelocities& walls, double dt,
                          double tolerance, bool on_faces, bool cells_from_faces, int max_products, FluidSolver& solver, FluidState& state,
                          std::vector<BodyCoupling>& coupling, CellField& increment_x, CellField& increment_y,
                          FaceField& face_increment_x, FaceField& face_increment_y, NoSlipWorkspace& work,
                          const BodyResponse& response = {}, MarkerPreconditioner* preconditioner = nullptr);

}  // namespace ibms
