// One step n -> n+1 of METHOD.md §7. Read top to bottom; each line is one substep.
// Scenes without bodies run only the predictor and the projection.
#include "sim/simulation.hpp"

namespace ibms {

void advance_one_step(Simulation& sim, double dt) {
  FluidState& fluid = sim.fluid();
  StageTimers& timers = sim.timers();
  const double time_n = fluid.time;
  if (sim.has_bodies()) {
    auto t = timers.time(Stage::schedules);
    apply_swelling_schedules(sim.swelling(), time_n, sim.bodies());  // D(t^n), M at constant density, §1.8
    prepare_markers(sim.bodies(), sim.swelling(), time_n, fluid.time_step_prev, sim.grid(),
                    sim.scene().ibm.sub_markers, sim.coupling(),
                    sim.scene().ibm.marker_retraction * sim.grid().dx());  // X^n, dV_l, U_target, §1.8, §3.6
  }
  const auto force_markers = [&](CellField& velocity_x, CellField& velocity_y) {
    auto t = timers.time(Stage::ib_forcing);
    apply_direct_forcing(sim.grid(), sim.kernel(), wall_velocities_at(sim.boundaries(), time_n), dt,
                         sim.scene().ibm.forcing_passes, sim.coupling(), velocity_x,
                         velocity_y);  // F = (U_target - J u)/dt, u += dt S F, §3.5
  };
  FluidSolver& solver = sim.fluid_solver();
  if (sim.has_bodies() && sim.forces_explicit_estimate()) {
    // Uhlmann (2005) steps 1-5: force the explicit estimate, the force enters the implicit solve.
    { auto t = timers.time(Stage::predictor); solver.predict_explicit(fluid, dt); }  // u~_e
    force_markers(solver.velocity_star_x(), solver.velocity_star_y());               // u~_e + dt f
    { auto t = timers.time(Stage::predictor); solver.complete_prediction(fluid, dt); }  // u~ with f
  } else {
    { auto t = timers.time(Stage::predictor); solver.predict_momentum(fluid, dt, nullptr, nullptr); }  // u~, §2.3
    if (sim.has_bodies()) force_markers(solver.velocity_star_x(), solver.velocity_star_y());  // u~ + dt f
  }
  {
    auto t = timers.time(Stage::projection);
    sim.last_projection = sim.fluid_solver().project_smac(fluid, dt);  // u^{n+1}, U_f^{n+1}, p^{n+1}
  }
  if (sim.has_bodies()) {
    auto t = timers.time(Stage::bodies);
    compute_fluid_reaction(sim.fluid_density(), sim.coupling());  // F_f,l = -rho_f sum F_l dV_l, §1.6
    sim.inner_fluid_inertia(sim.grid(), sim.fluid_density(), fluid, sim.bodies(), dt,
                            sim.coupling());  // F_int = rho_f dI/dt (variant K) or 0 (A), §1.7
    compute_hydrodynamic_loads(sim.bodies(), sim.coupling());  // F, T of the fluid on each body (eq. 1.7a)
    sim.last_contact_stats = ContactStats{};
    // Each group of bodies that may touch within the step takes its own sub-step; contact sub-steps
    // only for a group that may touch something (issues 10 and 12).
    SubstepGroups& groups = sim.substep_groups(dt);
    const double global_limit = groups.group_of.empty() ? sim.global_contact_limit(dt) : HUGE_VAL;
    const SolidStepCount count =
        advance_bodies({time_n, dt, sim.fluid_density(), sim.scene().fluid.gravity, global_limit,
                        sim.fixed_solid_substeps, &sim.spectral_workspace, &sim.implicit_systems},
                       sim.swelling(), sim.contact_forces, groups, sim.coupling(), sim.contact_work(), sim.rigid(),
                       sim.bodies());  // sub-steps by body kind, §5.3
    sim.last_n_substeps = count.max_substeps;
    sim.last_body_substeps = count.body_substeps;
    sim.total_substeps += count.max_substeps;
    sim.total_body_substeps += count.body_substeps;
    sim.total_contact_work += groups.contact_work;
  }
}

}  // namespace ibms
