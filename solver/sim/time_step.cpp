// One step n -> n+1 of docs/method.md §7. advance_one_step reads as the method: one call per
// sub-step, each timed inside. Scenes without bodies run only the prediction, the projection and
// the clock.
#include <algorithm>
#include <cmath>

#include "sim/no_slip_coupling.hpp"
#include "sim/simulation.hpp"

namespace ibms {

namespace {

// 1. D(t^n) and M at constant density (§1.8); markers X^n, dV_l and U_target (§1.8, §3.6).
void prepare_bodies(Simulation& sim, double time_n) {
  auto t = sim.timers().time(Stage::schedules);
  const FluidState& fluid = sim.fluid();
  apply_swelling_schedules(sim.swelling(), time_n, sim.bodies());
  prepare_markers(sim.bodies(), sim.swelling(), time_n, fluid.time_step_prev, sim.grid(), sim.scene().ibm.sub_markers,
                  sim.coupling(), sim.scene().ibm.marker_retraction * sim.grid().dx());
}

// F = (U_target - J u)/dt in forcing passes, u += dt S F (§3.5), on velocity_star.
void force_markers(Simulation& sim, double time_n, double dt) {
  auto t = sim.timers().time(Stage::ib_forcing);
  FluidSolver& solver = sim.fluid_solver();
  apply_direct_forcing(sim.grid(), sim.kernel(), wall_velocities_at(sim.boundaries(), time_n), dt,
                       sim.scene().ibm.forcing_passes, sim.coupling(), solver.velocity_star_x(), solver.velocity_star_y());
}

// 2. The momentum prediction u~ (§2.3) with the immersed-boundary force (§3.1):
//  - no_slip coupling: the previous step's forces in the Crank-Nicolson solve (when the markers
//    are the same; otherwise as Uhlmann);
//  - Uhlmann (2005) steps 1-5: force the explicit estimate, the force enters the implicit solve;
//  - ibm.forcing_stage = "implicit_prediction": force the Crank-Nicolson prediction.
void predict(Simulation& sim, double time_n, double dt) {
  FluidState& fluid = sim.fluid();
  FluidSolver& solver = sim.fluid_solver();
  if (!sim.has_bodies()) {
    auto t = sim.timers().time(Stage::predictor);
    solver.predict_momentum(fluid, dt, nullptr, nullptr);
    return;
  }
  if (sim.enforces_no_slip() || sim.forces_explicit_estimate()) {
    { auto t = sim.timers().time(Stage::predictor); solver.predict_explicit(fluid, dt); }  // u~_e
    bool predicted = false;
    if (sim.enforces_no_slip()) {
      auto t = sim.timers().time(Stage::ib_forcing);
      predicted = spread_previous_forces(sim.grid(), sim.kernel(), dt, sim.coupling(), solver.velocity_star_x(),
                                         solver.velocity_star_y());  // u~_e + dt S F^{n-1}
    }
    if (!predicted) force_markers(sim, time_n, dt);                                        // u~_e + dt f
    if (sim.enforces_no_slip()) {
      auto t = sim.timers().time(Stage::ib_forcing);
      NoSlipArrays& ns = sim.no_slip;
      spread_step_forces(sim.grid(), sim.kernel(), dt, sim.coupling(), ns.force_cell_x, ns.force_cell_y,
                         ns.force_face_x, ns.force_face_y);  // dt S F, dt S_f F for the faces
      if (sim.cell_forces_from_faces())
        cell_forces_from_faces(sim.grid(), ns.force_face_x, ns.force_face_y, ns.force_cell_x, ns.force_cell_y,
                               solver.velocity_star_x(), solver.velocity_star_y());  // dt A S_f F
    }
    { auto t = sim.timers().time(Stage::predictor); solver.complete_prediction(fluid, dt); }  // u~ with f
  } else {
    { auto t = sim.timers().time(Stage::predictor); solver.predict_momentum(fluid, dt, nullptr, nullptr); }  // u~
    force_markers(sim, time_n, dt);                                                                         // u~ + dt f
  }
}

// 3. u^{n+1}, U_f^{n+1}, p^{n+1} (§2.3 steps 3-5).
void project(Simulation& sim, double dt) {
  auto t = sim.timers().time(Stage::projection);
  NoSlipArrays& ns = sim.no_slip;
  const FaceForcing balanced{&ns.force_cell_x, &ns.force_cell_y, &ns.force_face_x, &ns.force_face_y};
  sim.stats.last_projection = sim.fluid_solver().project(sim.fluid(), dt, sim.enforces_no_slip() ? &balanced : nullptr);
}

// The no_slip coupling's mass-spring bodies (§3.7): the backward-Euler step of each over dt without
// the fluid, from x^n, U^n with its springs, dashpots and buoyant weight, factorised for the
// response; its velocity change joins the target (the rim velocity at the end of the step). Returns
// whether any body responds.
bool prepare_body_responses(Simulation& sim, double dt) {
  bool any = false;
  const Vec2& gravity = sim.scene().fluid.gravity;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    BodyCoupling& c = sim.coupling()[b];
    if (c.body_velocity_change.empty()) continue;
    const MassSpringBody& body = sim.bodies()[b];
    for (int p = 0; p < body.n_points(); ++p)
      c.external_force[p] = body.buoyant_weight(body.mass[p], sim.fluid_density(), gravity);
    sim.no_slip.response_systems[b].velocity_change(body, dt, c.external_force);  // dU without the fluid
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) c.target_velocity[l][d] += c.external_force[l][d];
    any = true;
  }
  return any;
}

// 4. The slip at t^{n+1} (§3.7); with the no_slip coupling, force corrections projected with the
// pressure until no-slip holds at every marker (sim/no_slip_coupling.hpp).
void hold_no_slip(Simulation& sim, double time_n, double dt) {
  auto t = sim.timers().time(Stage::ib_forcing);
  FluidState& fluid = sim.fluid();
  const WallVelocities walls = wall_velocities_at(sim.boundaries(), time_n + dt);
  if (!sim.enforces_no_slip()) {
    measure_face_slip(sim.grid(), sim.kernel(), walls, fluid.velocity_face_x, fluid.velocity_face_y, sim.coupling());
    measure_slip(sim.grid(), sim.kernel(), walls, fluid.velocity_x, fluid.velocity_y, sim.coupling());
    return;
  }
  const IbmSpec& ibm = sim.scene().ibm;
  const bool on_faces = ibm.constrained_velocity == IbmSpec::ConstrainedVelocity::faces;
  const bool responds = prepare_body_responses(sim, dt);
  // -(M + dt D + dt^2 S)^{-1} rho_f dV (dt F) on the rim points of body b (markers = rim points).
  const BodyResponse response = [&sim](std::size_t b, const std::vector<Vec2>& impulse, std::vector<Vec2>& change) {
    BodyCoupling& c = sim.coupling()[b];
    std::vector<double>& x = c.response_work;
    std::fill(x.begin(), x.end(), 0.0);
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) x[2 * l + d] = -sim.fluid_density() * c.marker_volume[l] * impulse[l][d];
    sim.no_slip.response_systems[b].response(x);
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) change[l][d] = x[2 * l + d];
  };
  NoSlipArrays& ns = sim.no_slip;
  const NoSlipResult result =
      hold_no_slip(sim.grid(), sim.kernel(), walls, dt, ibm.slip_tolerance, on_faces, sim.cell_forces_from_faces(),
                   ibm.max_coupling_iterations, sim.fluid_solver(), fluid, sim.coupling(), ns.slip_increment_x,
                   ns.slip_increment_y, ns.force_face_x, ns.force_face_y, ns.work, responds ? response : BodyResponse{});
  keep_forces(sim.coupling());
  // The slip of the velocity not constrained, for the series: cells and faces differ by the
  // momentum interpolation's dt (mean(G_c) - G_f) p (§2.3).
  if (on_faces)
    measure_slip(sim.grid(), sim.kernel(), walls, fluid.velocity_x, fluid.velocity_y, sim.coupling());
  else
    measure_face_slip(sim.grid(), sim.kernel(), walls, fluid.velocity_face_x, fluid.velocity_face_y, sim.coupling());
  sim.stats.last_coupling_iterations = result.products;
  sim.stats.total_coupling_iterations += result.products;
  if (result.products > 0) {
    // The corrections changed u^{n+1}: its largest speed anew, its change since u^n at most by their sum.
    double largest = 0.0;
    for (int j = 0; j < sim.grid().ny; ++j)
      for (int i = 0; i < sim.grid().nx; ++i)
        largest = std::max({largest, std::abs(fluid.velocity_x(i, j)), std::abs(fluid.velocity_y(i, j))});
    sim.stats.last_projection.max_velocity = largest;
    sim.stats.last_projection.max_velocity_change += result.max_change;
  }
}

// 6. The fluid on the bodies and the bodies' sub-steps (§1.6, §1.7, §5.3).
void advance_body_stage(Simulation& sim, double time_n, double dt) {
  auto t = sim.timers().time(Stage::bodies);
  compute_fluid_reaction(sim.fluid_density(), sim.coupling());  // F_f,l = -rho_f sum F_l dV_l, §1.6
  sim.inner_fluid_inertia(sim.grid(), sim.fluid_density(), sim.fluid(), sim.bodies(), dt,
                          sim.coupling());  // F_int = rho_f dI/dt (variant K) or 0 (A), §1.7
  compute_hydrodynamic_loads(sim.bodies(), sim.coupling());  // F, T of the fluid on each body (eq. 1.7a)
  sim.stats.last_contact_stats = ContactStats{};
  // Each group of bodies that may touch within the step takes its own sub-step; contact sub-steps
  // only for a group that may touch something.
  SubstepGroups& groups = sim.substep_groups(dt);
  const double global_limit = groups.group_of.empty() ? sim.substep_planner().global_contact_limit(dt) : HUGE_VAL;
  for (RigidBody& r : sim.rigid()) start_fluid_step(r);
  SolidSubstepWork& work = sim.solid_work;
  const SolidStepCount count =
      advance_bodies({time_n, dt, sim.fluid_density(), sim.scene().fluid.gravity, global_limit, work.fixed_substeps,
                      &work.spectral_workspace, &work.implicit_systems},
                     sim.swelling(), sim.contact_forces, groups, sim.coupling(), sim.contact_work(), sim.rigid(),
                     sim.bodies());
  for (RigidBody& r : sim.rigid()) end_fluid_step(dt, r);
  RunStatistics& stats = sim.stats;
  stats.last_n_substeps = count.max_substeps;
  stats.last_body_substeps = count.body_substeps;
  stats.total_substeps += count.max_substeps;
  stats.total_body_substeps += count.body_substeps;
  stats.total_contact_work += groups.contact_work;
}

}  // namespace

void advance_one_step(Simulation& sim, double dt) {
  const double time_n = sim.fluid().time;
  if (sim.has_bodies()) prepare_bodies(sim, time_n);            // 1. D(t^n), X^n, U_target
  predict(sim, time_n, dt);                                     // 2. u~ with the IB force
  project(sim, dt);                                             // 3. u^{n+1}, U_f^{n+1}, p^{n+1}
  if (sim.has_bodies()) hold_no_slip(sim, time_n, dt);          // 4. slip at t^{n+1}; no_slip: corrections
  sim.fluid_solver().end_step(sim.fluid(), dt);                 // 5. t^{n+1}, AB2 history
  if (sim.has_bodies()) advance_body_stage(sim, time_n, dt);    // 6. bodies to t^{n+1}
}

}  // namespace ibms
