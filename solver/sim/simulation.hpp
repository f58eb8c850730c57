// The Simulation: everything one run holds (grid, fluid solver and state, stage list, timers),
// built once from a validated Scene. sim/ is the only place where modules meet (docs/design.md §2).
// Schemes and stages are chosen here, when the Simulation is built, never inside the step:
// the IB kernel, the inner-fluid inertia variant (docs/method.md §1.7) and the contact hook.
// Bodies, their swelling schedules and all coupling work arrays are allocated here, once.
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
#include "solid/mass_spring_body.hpp"
#include "solid/rigid_motion.hpp"
#include "solid/swelling_schedule.hpp"

namespace ibms {

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

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

  InnerFluidInertia inner_fluid_inertia = nullptr;  // variant K or A, from ibm.inner_fluid_inertia
  ContactForces contact_forces = no_contact_forces; // the contact seam (solver/contact wires in here)
  // The contacts' inner loop (contact.time_stepping = "inner_loop"; empty: shared sub-steps).
  ContactInnerLoop contact_inner_loop;
  long total_contact_inner_steps = 0;  // inner contact steps over the run, summed over groups [-]

  // DEM contacts (solver/contact), active when contact.stiffness > 0 or contact.model = "collision_time".
  bool has_contacts() const { return contact_model_.enabled(); }
  // The model of the latest step (collision_time: T_c of that step; for_fluid_step gives another dt's).
  const ContactModel& contact_model() const { return contact_model_; }
  // Whether a contact can be under way within the next step of length dt (contact/contact_model.hpp);
  // false without contacts. Only then does the contact sub-step bound apply.
  bool contact_possible(double dt) const;
  // The instability guard (sim/diagnostics.cpp): the speed that drives the scene, V_drive = the
  // largest of the wall speeds, the initial body point speeds, the prescribed bodies' point speeds,
  // the swelling rates and the free-fall speed sqrt(2 |1 - rho_f/rho_s| |g| L) over the box
  // diagonal L (at least L / 1000 per end_time); and per body the most kinetic energy it can physically reach,
  // E_max = 4 (M V_drive^2 / 2 + E_spring(t = 0)) with M its largest (swollen) mass.
  double driving_speed() const { return driving_speed_; }
  // M V_drive^2 / 2 + E_spring(t = 0) of each body; the bound is instability_energy_factor times it.
  const std::vector<double>& body_energy_scale() const { return body_energy_scale_; }
  static constexpr double instability_energy_factor = 4.0;  // twice every speed
  mutable bool instability_warned = false;  // run.on_body_instability = "warn": said once
  // Work of the contact forces on all bodies since t = 0 [energy/length]: never positive for the
  // dissipative spring-dashpot law with walls at rest, apart from the integration error; a contact
  // that returns more energy than it received makes it grow (the guard in sim/diagnostics.cpp).
  double total_contact_work = 0.0;
  // The fluid's energy budget and speed bound (sim/fluid_guard.hpp), started from the state the
  // Simulation is built with and again by run_simulation.
  FluidGuard fluid_guard;
  // How the bodies sub-step in the next step of length dt (sim/body_update.hpp): the contact groups
  // with the contact sub-step bound of each group that may touch something; with
  // run.solid_substeps = "global", no groups (one group, bound global_contact_limit(dt)).
  SubstepGroups& substep_groups(double dt);
  void plan_substep_groups(double dt, SubstepGroups& groups) const;  // the same into `groups`
  // Sub-steps body b took in the latest step (0 before the first).
  int body_substeps(std::size_t b) const {
    return b < substep_groups_.substeps_of_body.size() ? substep_groups_.substeps_of_body[b] : 0;
  }
  // The global bound (run.solid_substeps = "global"): the contact sub-step of all bodies if any
  // contact is possible.
  double global_contact_limit(double dt) const;
  ContactStats last_contact_stats;  // merged over the sub-steps of the latest step
  long total_pair_checks = 0;       // CDS pairs examined by the pair search over the run [-]
  // Pair search runs only with contacts and two or more bodies (docs/design.md §3: one body, no pair search).
  bool has_pair_search() const { return has_contacts() && bodies_.size() > 1; }
  // > 0: the solid takes exactly this many sub-steps per fluid step, ignoring its stability bound
  // (bench/bench_stability.cpp's fixed-step runs); 0: automatic sub-stepping (docs/method.md §5.3).
  int fixed_solid_substeps = 0;
  SpectralWorkspace spectral_workspace;  // scratch of the solid sub-step bound, reused every step
  std::vector<ImplicitSpringSystem> implicit_systems;  // per body: storage of the implicit spring step
  // ibm.coupling = "no_slip": per body, the linearised response of a mass-spring body over the
  // fluid step, (M + dt D + dt^2 S) factorised at the step's start (docs/method.md §3.7).
  std::vector<ImplicitSpringSystem> response_systems;

  ProjectionStats last_projection;  // diagnostics of the latest step
  // ibm.coupling = "no_slip": the projected increment of one correction (allocated once), and the
  // corrections of the latest step and of the run.
  CellField slip_increment_x, slip_increment_y;
  // ibm.coupling = "no_slip": the step's force dt S F on the cells and dt S_f F on the faces (the
  // balanced momentum interpolation, FaceForcing); after the projection the faces are the scratch
  // of the corrections' face increments.
  CellField force_cell_x, force_cell_y;
  FaceField force_face_x, force_face_y;
  NoSlipWorkspace no_slip_work;
  int last_coupling_iterations = 0;
  long total_coupling_iterations = 0;
  int last_n_substeps = 0;          // solid sub-steps of the latest step, most of any group [-]
  long last_body_substeps = 0;      // solid sub-steps of the latest step summed over bodies [-]
  long total_substeps = 0;          // solid sub-steps since the Simulation was built (most of any group) [-]
  long total_body_substeps = 0;     // the same summed over bodies: the work of the solid [-]

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
  mutable std::vector<double> contact_reach_;  // scratch of contact_possible, one entry per body
  double driving_speed_ = 0.0;
  std::vector<double> body_energy_scale_;
  void set_instability_bounds();
  mutable ContactGroups contact_groups_;       // scratch of contact_possible and substep_groups
  SubstepGroups substep_groups_;
  void find_groups(double dt) const;           // contact_groups_ for a step of length dt
};

// Builders shared with `ibms info` and tests.
Grid grid_from_scene(const Scene& scene);
FluidBoundaries boundaries_from_scene(const Scene& scene);

// One step n -> n+1 of docs/method.md §7 (sim/time_step.cpp).
void advance_one_step(Simulation& sim, double dt);

}  // namespace ibms
