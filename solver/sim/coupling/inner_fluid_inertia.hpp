// The inner-fluid inertia term rho_f dI/dt of the body momentum balance (docs/method.md §1.7, eq. 1.7a).
// Variant K ("kempe", default): I_T = sum_ij alpha_T(i,j) u_ij h^2 over the fan triangles
// T_l = (c, l, l+1) with exact clipped cell areas alpha_T h^2 (ibm/triangle_cell_overlap), and
//   F_int,T = rho_f (I_T(X^n, u^{n+1}) - I_T(X^{n-1}, u^n)) / dt,
// the Reynolds-transport form of §1.7 step 3, each third to the three vertices of T (§1.7 step 4).
// Why this form rather than the fixed-region difference: its increments telescope, so
//   sum_ij rho_f u h^2 - rho_f sum_T I_T + sum_i M_i U_i   (outer fluid + bodies)
// is conserved to round-off in a periodic box; the fixed-region form drops the momentum flux
// through the moving surface and would not be. Cost: one overlap pass per body and step.
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
void no_inner_fluid_inertia(const Grid& grid, double fluid_density, const FluidState& fluid,
                            const std::vector<MassSpringBody>& bodies, double dt,
                            std::vector<BodyCoupling>& coupling);

// The variant ibm.inner_fluid_inertia selects: kempe (K) or none (A).
InnerFluidInertia inner_fluid_inertia_of(IbmSpec::InnerFluidInertia variant);

// rho_f sum_T I_T over all bodies (the stored I of the latest step) [mass length/time per depth].
Vec2 inner_fluid_momentum(double fluid_density, const std::vector<BodyCoupling>& coupling);

}  // namespace ibms
