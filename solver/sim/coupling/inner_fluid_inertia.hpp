// The inner-fluid inertia term rho_f dI/dt of the body momentum balance (docs/method.md §1.7, eq. 1.7a).
// Variant K ("kempe", default): I_T = sum_ij alpha_T(i,j) u_ij h^2 over the fan triangles
// T_l = (c, l, l+1) with exact clipped cell areas alpha_T h^2 (ibm/triangle_cell_overlap), and
//   F_int,T = rho_f (I_T(X^n, u^{n+1}) - I_T(X^{n-1}, u^n)) / dt,
// the Reynolds-transport form of §1.7 step 3, each third to the three vertices of T (§1.7 step 4).
// Why this form rather than the fixed-region difference: its increments telescope, so
//   sum_ij rho_f u h^2 - rho_f sum_T I_T + sum_i M_i U_i   (outer fluid + bodies)
// is conserved to round-off in a periodic box; the fixed-region form drops the momentum flux
// through the moving surface and would not be. Cost: one overlap pass per body and step.
// "kempe_by_mass": the same F_int,T summed to the body's force F and torque T about X_c^n (rho_f dI/dt,
// rho_f dL/dt), laid on the points as the load of a rigid motion of their masses,
//   f_p = m_p (A + alpha z x (x_p - x_G)),  M A = F,  J_G alpha = T_G (about the centre of mass x_G).
// Why: the inner fluid is moved by the rim's markers only, yet a third of each triangle's force on
// the centre point puts a third of the body's F_int on a point of 1/(N_l + 1) of its mass
// (equal lumping) that the fluid does not see: (N_l + 1)/3 rho_f/rho_s times the inner fluid's
// acceleration, a step late, drives the undamped hub mode (centre against rim) of a light wheel
// (validation/cavity_swelling_particles/README.md, 256 particles). A rigid-motion load gives every
// point the same acceleration from a uniform one of the inner fluid and excites no internal mode;
// F and T, and with them the momentum conservation below, are those of "kempe".
// Variant A ("none", the papers' literal form): F_int = 0.
#pragma once
#include <vector>

#include "fluid/fluid_solver.hpp"
#include "scene/scene.hpp"
#include "sim/coupling/body_coupling.hpp"

namespace ibms {

// I_T of every triangle at the bodies' current positions with `fluid`'s velocity, stored in
// coupling.triangle_momentum (and the cells in coupling.triangle_cells). Used at t = 0.
void sample_inner_fluid_momentum(const Grid& grid, const FluidState& fluid,
                                 const std::vector<MassSpringBody>& bodies,
                                 std::vector<BodyCoupling>& coupling);

// The step's inner-fluid force, chosen when the Simulation is built (no switch in the step).
// Called after the projection with X^n still in the bodies and u^{n+1} in `fluid`.
using InnerFluidInertia = void (*)(const Grid& grid, double fluid_density, const FluidState& fluid,
                                   const std::vector<MassSpringBody>& bodies, double dt,
                                   std::vector<BodyCoupling>& coupling);

void kempe_inner_fluid_inertia(const Grid& grid, double fluid_density, const FluidState& fluid,
                               const std::vector<MassSpringBody>& bodies, double dt,
                               std::vector<BodyCoupling>& coupling);
void kempe_inner_fluid_inertia_by_mass(const Grid& grid, double fluid_density, const FluidState& fluid,
                                       const std::vector<MassSpringBody>& bodies, double dt,
                                       std::vector<BodyCoupling>& coupling);
void no_inner_fluid_inertia(const Grid& grid, double fluid_density, const FluidState& fluid,
                            const std::vector<MassSpringBody>& bodies, double dt,
                            std::vector<BodyCoupling>& coupling);

// The variant ibm.inner_fluid_inertia selects: kempe (K), kempe_by_mass (K, rigid-motion load) or none (A).
InnerFluidInertia inner_fluid_inertia_of(IbmSpec::InnerFluidInertia variant);

// rho_f sum_T I_T over all bodies (the stored I of the latest step) [mass length/time per depth].
Vec2 inner_fluid_momentum(double fluid_density, const std::vector<BodyCoupling>& coupling);

}  // namespace ibms
