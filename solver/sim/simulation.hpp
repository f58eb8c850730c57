// The Simulation: everything one run holds (grid, fluid solver and state, stage list, timers,
// bodies and their coupling), built once from a validated Scene. sim/ is the only place where
// modules meet (docs/design.md §2). Schemes and stages are chosen here, when the Simulation is
// built, never inside the step: the IB kernel, the inner-fluid inertia variant (docs/method.md
// §1.7) and the contact hook. Bodies, their swelling schedules and all coupling work arrays are
// allocated here, once. What the steps keep is held in named parts: RunStatistics (what the steps
// did), InstabilityBounds (the guards' scales), NoSlipArrays (sim/no_slip_coupling.hpp),
// SolidSubstepWork, and the SubstepPlanner (sim/substep_planning.hpp).
#pragma once
#include <string>
#include <vector>

#include "contact/contact_forces.hpp"
#include "contact/contact_model.hpp"
#include "contact/contact_subcycle.hpp"
#include "core/grid.hpp"
#include "fluid/fluid_solver.hpp"
#include "ibm/delta_kernel.hpp"
#include "scene/scene.hpp"
#include "sim/body_coupling.hpp"
#include "sim/body_update.hpp"
#include "sim/fluid_guard.hpp"
#include "sim/inner_fluid_inertia.hpp"
#include "sim/no_slip_coupling.hpp"
#include "sim/stage_timers.hpp"
#include "sim/substep_planning.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/rigid_motion.hpp"
#include "solid/swelling_schedule.hpp"

namespace ibms {

// What the steps did: the latest step's figures and the totals since the Simulation was built
// (the series, /timing, tests and benchmarks read them).
struct RunStatistics {
  ProjectionStats last_projection;  // diagnostics of the latest step's projection
  ContactStats last_contact_stats;  // merged over the sub-steps of the latest step
  int last_coupling_iterations = 0; // no_slip: J P_0 S products of the latest step [-]
  int last_n_substeps = 0;          // solid sub-steps of the latest step, most of any group [-]
  long last_body_substeps = 0;      // solid sub-steps of the latest step summed over bodies [-]
  long total_coupling_iterations = 0;  // no_slip: J P_0 S products over the run [-]
  long total_substeps = 0;          // solid sub-steps over the run (most of any group) [-]
  long total_body_substeps = 0;     // the same summed over bodies: the work of the solid [-]
  long total_contact_inner_steps = 0;  // inner contact steps over the run, summed over groups [-]
  long total_pair_checks = 0;       // CDS pairs examined by the pair search over the run [-]
  // Work of the contact forces on all bodies since t = 0 [energy/length]: never positive for the
  // dissipative spring-dashpot law with walls at rest, apart from the integration error; a contact
  // that returns more energy than it received makes it grow (the guard in sim/diagnostics.cpp).
  double total_contact_work = 0.0;
};

// The instability guards' scales (sim/diagnostics.cpp, sim/fluid_guard.hpp). driving_speed is the
// speed that drives the scene, V_drive = the largest of the wall speeds, the initial body point
// speeds, the prescribed bodies' point speeds, the swelling rates and the free-fall speed
// sqrt(2 |1 - rho_f/rho_s| |g| L) over the box diagonal L (at least L / 1000 per end_time); per
// body, the most kinetic energy it can physically reach is E_max = energy_factor (M V_drive^2 / 2 +
// E_spring(t = 0)), M its largest (swollen) mass.
struct InstabilityBounds {
  static constexpr double energy_factor = 4.0;  // twice every speed
  double driving_speed = 0.0;
  std::vector<double> body_energy_scale;  // M V_drive^2 / 2 + E_spring(t = 0) of each body
  mutable bool warned = false;  // run.on_body_instability = "warn": said once
  // The fluid's energy budget and speed bound, started from the state the Simulation is built
  // with and again by run_simulation.
  FluidGuard fluid_guard;
};

// Storage the bodies' sub-steps reuse every step (sim/body_update.hpp, SolidStepInputs).
struct SolidSubstepWork {
  // > 0: the solid takes exactly this many sub-steps per fluid step, ignoring its stability bound
  // (bench/bench_stability.cpp's fixed-step runs); 0: automatic sub-stepping (docs/method.md §5.3).
  int fixed_substeps = 0;
  SpectralWorkspace spectral_workspace;  // scratch of the solid sub-step bound
  std::vector<ImplicitSpringSystem> implicit_systems;  // per body: storage of the implicit spring step
};

class Simulation {
 public:
  explicit Simulation(const Scene& scene);
  // The contact seams and the sub-step planner refer to this object's members: it stays where it is built.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const Scene& scene() const { return scene_; }
  const Grid& grid() const { return grid_; }
  FluidSolver& fluid_solver() { return fluid_solver_; }
  const FluidSolver& fluid_solver() const { return fluid_solver_; }
  FluidState& fluid() { return fluid_; }
  const FluidState& fluid() const { return fluid_; }
  StageTimers& timers() { return timers_; }
  const StageTimers& timers() const { return timers_; }
  double fluid_density() const { return scene_.fluid.density; }

  bool has_bodies() const { return scene_.has_bodies(); }
  // ibm.forcing_stage: the markers force the explicit estimate (Uhlmann 2005) or the CN prediction.
  bool forces_explicit_estimate() const { return scene_.ibm.forcing_stage == IbmSpec::ForcingStage::explicit_estimate; }
  // ibm.coupling = "no_slip": the forces are corrected until no-slip holds at t^{n+1}.
  bool enforces_no_slip() const { return has_bodies() && scene_.ibm.coupling == IbmSpec::Coupling::no_slip; }
  // Under the face constraint the cells take the force as the mean of its face values, as they take
  // the pressure gradient (docs/method.md §3.7).
  bool cell_forces_from_faces() const {
    return enforces_no_slip() && scene_.ibm.constrained_velocity == IbmSpec::ConstrainedVelocity::faces;
  }
  // Names of the pipeline stages this scene runs, in order (`ibms info` prints them).
  std::vector<std::string> stage_names() const;

  // Bodies (docs/method.md §1), in scene order, and what couples them to the fluid.
  std::vector<MassSpringBody>& bodies() { return bodies_; }
  const std::vector<MassSpringBody>& bodies() const { return bodies_; }
  const std::vector<SwellingSchedule>& swelling() const { return swelling_; }
  // Motion of the rigid and prescribed bodies (entry b unused for a mass_spring body).
  std::vector<RigidBody>& rigid() { return rigid_; }
  const std::vector<RigidBody>& rigid() const { return rigid_; }
  std::vector<BodyCoupling>& coupling() { return coupling_; }
  const std::vector<BodyCoupling>& coupling() const { return coupling_; }
  std::vector<std::vector<Vec2>>& contact_work() { return contact_work_; }
  KernelKind kernel() const { return kernel_; }
  const FluidBoundaries& boundaries() const { return fluid_solver_.boundaries(); }

  // The stages chosen when the Simulation is built.
  InnerFluidInertia inner_fluid_inertia = nullptr;  // variant K or A, from ibm.inner_fluid_inertia
  ContactForces contact_forces = no_contact_forces; // the contact seam (solver/contact wires in here)
  // The contacts' inner loop (contact.time_stepping = "inner_loop"; empty: shared sub-steps).
  ContactInnerLoop contact_inner_loop;

  // DEM contacts (solver/contact), active when contact.stiffness > 0 or contact.model = "collision_time".
  bool has_contacts() const { return contact_model_.enabled(); }
  // The model of the latest step (collision_time: T_c of that step; for_fluid_step gives another dt's).
  const ContactModel& contact_model() const { return contact_model_; }
  // Pair search runs only with contacts and two or more bodies (docs/design.md §3: one body, no pair search).
  bool has_pair_search() const { return has_contacts() && bodies_.size() > 1; }
  // Which bodies sub-step together and at which contact bound (sim/substep_planning.hpp).
  const SubstepPlanner& substep_planner() const { return substep_planner_; }
  // The plan of the step of length dt, with the contact law of that step (collision_time:
  // T_c = collision_steps dt), which the contact seams read.
  SubstepGroups& substep_groups(double dt);

  RunStatistics stats;
  InstabilityBounds instability;  // set when the Simulation is built; the fluid guard runs with it
  NoSlipArrays no_slip;           // allocated when ibm.coupling = "no_slip"
  SolidSubstepWork solid_work;

 private:
  Scene scene_;
  Grid grid_;
  FluidSolver fluid_solver_;
  FluidState fluid_;
  StageTimers timers_;
  KernelKind kernel_;
  std::vector<MassSpringBody> bodies_;
  std::vector<SwellingSchedule> swelling_;
  std::vector<RigidBody> rigid_;
  std::vector<BodyCoupling> coupling_;
  std::vector<std::vector<Vec2>> contact_work_;
  ContactModel contact_model_;
  WallBox contact_box_;
  SubstepPlanner substep_planner_;
  void set_instability_bounds();
};

// Builders shared with `ibms info` and tests.
Grid grid_from_scene(const Scene& scene);
FluidBoundaries boundaries_from_scene(const Scene& scene);

// One step n -> n+1 of docs/method.md §7 (sim/time_step.cpp).
void advance_one_step(Simulation& sim, double dt);

}  // namespace ibms
