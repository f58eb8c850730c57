// One step n -> n+1 of docs/method.md §7. advance_one_step reads as the method: one call per
// sub-step, each timed inside. The coupling object chosen when the Simulation was built
// (sim/coupling/coupling.hpp) does the immersed-boundary part of steps 2-4; scenes without bodies
// run only the prediction, the projection and the clock.
#include "sim/time_step.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

namespace {

// 1. D(t^n) and M at constant density (§1.8); markers X^n, dV_l and U_target (§1.8, §3.6).
void prepare_bodies(Simulation& sim, double time_n) {
  auto t = sim.timers().time(Stage::schedules);
  const FluidState& fluid = sim.fluid();
  apply_swelling_schedules(sim.swelling(), time_n, sim.bodies());
  prepare_markers(sim.bodies(), sim.swelling(), time_n, fluid.time_step_prev, sim.grid(), sim.scene().ibm.sub_markers,
                  sim.markers(), sim.scene().ibm.marker_retraction * sim.grid().dx());
}

// 3. u^{n+1}, U_f^{n+1}, p^{n+1} (§2.3 steps 3-5), balancing the coupling's force on cells and faces.
void project(Simulation& sim, double dt) {
  auto t = sim.timers().time(Stage::projection);
  sim.stats().last_projection = sim.fluid_solver().project(sim.fluid(), dt, sim.coupling().projection_forcing());
}

// What the coupling's hold stage did, in the statistics: its products, and, when its corrections
// changed u^{n+1}, the largest speed anew and the change since u^n at most by their sum.
void record_coupling(Simulation& sim, const CouplingWork& work) {
  RunStatistics& stats = sim.stats();
  stats.last_coupling_iterations = work.products;
  stats.total_coupling_iterations += work.products;
  if (work.products == 0) return;
  const FluidState& fluid = sim.fluid();
  double largest = 0.0;
  for (int j = 0; j < sim.grid().ny; ++j)
    for (int i = 0; i < sim.grid().nx; ++i)
      largest = std::max({largest, std::abs(fluid.velocity_x(i, j)), std::abs(fluid.velocity_y(i, j))});
  stats.last_projection.max_velocity = largest;
  stats.last_projection.max_velocity_change += work.max_change;
}

// 6. The fluid on the bodies and the bodies' sub-steps (§1.6, §1.7, §5.3).
void advance_body_stage(Simulation& sim, double time_n, double dt) {
  auto t = sim.timers().time(Stage::bodies);
  compute_fluid_reaction(sim.fluid_density(), sim.markers());  // F_f,l = -rho_f sum F_l dV_l, §1.6
  sim.inner_fluid_inertia()(sim.grid(), sim.fluid_density(), sim.fluid(), sim.bodies(), dt,
                          sim.markers());  // F_int = rho_f dI/dt (variant K) or 0 (A), §1.7
  compute_hydrodynamic_loads(sim.bodies(), sim.markers());  // F, T of the fluid on each body (eq. 1.7a)
  sim.stats().last_contact_stats = ContactStats{};
  // Each group of bodies that may touch within the step takes its own sub-step; contact sub-steps
  // only for a group that may touch something.
  SubstepGroups& groups = sim.substep_groups(dt);
  const double global_limit = groups.group_of.empty() ? sim.substep_planner().global_contact_limit(dt) : HUGE_VAL;
  for (RigidBody& r : sim.rigid()) start_fluid_step(r);
  SolidSubstepWork& work = sim.solid_work();
  const SolidStepCount count =
      advance_bodies({time_n, dt, sim.fluid_density(), sim.scene().fluid.gravity, global_limit, work.fixed_substeps,
                      &work.spectral_workspace, &work.implicit_systems},
                     sim.swelling(), sim.contact_forces(), groups, sim.markers(), sim.contact_work(), sim.rigid(),
                     sim.bodies());
  for (RigidBody& r : sim.rigid()) end_fluid_step(dt, r);
  RunStatistics& stats = sim.stats();
  stats.last_n_substeps = count.max_substeps;
  stats.last_body_substeps = count.body_substeps;
  stats.total_substeps += count.max_substeps;
  stats.total_body_substeps += count.body_substeps;
  stats.total_contact_work += groups.contact_work;
}

}  // namespace

void advance_one_step(Simulation& sim, double dt) {
  const double time_n = sim.fluid().time;
  const CouplingStep step{sim.fluid_solver(), sim.fluid(), sim.markers(), sim.bodies(), sim.rigid(), sim.timers(),
                          time_n, dt};
  if (sim.has_bodies()) prepare_bodies(sim, time_n);            // 1. D(t^n), X^n, U_target
  sim.coupling().predict(step);                                 // 2. u~ with the IB force
  project(sim, dt);                                             // 3. u^{n+1}, U_f^{n+1}, p^{n+1}
  record_coupling(sim, sim.coupling().hold(step));              // 4. slip at t^{n+1}, held or measured
  sim.fluid_solver().end_step(sim.fluid());                     // 5. AB2 history: N^n becomes N^{n-1}
  sim.fluid().tick(dt);                                         //    the clock: t^{n+1}, n + 1
  if (sim.has_bodies()) advance_body_stage(sim, time_n, dt);    // 6. bodies to t^{n+1}
}

}  // namespace ibms
