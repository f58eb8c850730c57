// The Simulation: everything one run holds (grid, fluid solver and state, stage list, timers,
// bodies, their markers and the coupling), built once from a validated Scene. sim/ is the only
// place where modules meet (docs/design.md §2), in rooms: coupling/ (the coupling objects and the
// markers), bodies/ (the bodies' update and sub-step planning), checks/ (guards, blow-up,
// control volumes) and run/ (the loop, output, checkpoint) above this file, with the step
// (time_step.hpp) and its time-step limits (time_step_limits.hpp) beside it. Schemes and stages
// are chosen here, when the Simulation is built, never inside the step: the coupling object
// (sim/coupling/coupling.hpp), the IB kernel, the inner-fluid inertia variant (docs/method.md §1.7)
// and the contact seams. Bodies, their swelling schedules and all work arrays are allocated here,
// once. What the steps keep is held in named parts: RunStatistics (what the steps did),
// InstabilityBounds (the guards' scales, sim/instability_bounds.hpp), SolidSubstepWork, and the
// SubstepPlanner (sim/bodies/substep_planning.hpp).
#pragma once
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_forces.hpp"
#include "contact/contact_model.hpp"
#include "contact/contact_subcycle.hpp"
#include "core/grid.hpp"
#include "core/stage_timers.hpp"
#include "fluid/fluid_solver.hpp"
#include "ibm/delta_kernel.hpp"
#include "scene/scene.hpp"
#include "sim/bodies/body_update.hpp"
#include "sim/bodies/substep_planning.hpp"
#include "sim/coupling/body_coupling.hpp"
#include "sim/coupling/coupling.hpp"
#include "sim/coupling/inner_fluid_inertia.hpp"
#include "sim/instability_bounds.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/rigid_motion.hpp"
#include "solid/swelling_schedule.hpp"

namespace ibms {

// What the steps did: the latest step's figures and the totals since the Simulation was built
// (the series, /timing, tests and benchmarks read them).
struct RunStatistics {
  ProjectionStats last_projection;  // diagnostics of the latest step's projection
  ContactStats last_contact_stats;  // merged over the sub-steps of the latest step
  int last_coupling_iterations = 0; // the coupling's marker-system products of the latest step [-]
  int last_n_substeps = 0;          // solid sub-steps of the latest step, most of any group [-]
  long last_body_substeps = 0;      // solid sub-steps of the latest step summed over bodies [-]
  long total_coupling_iterations = 0;  // the same over the run [-]
  long total_substeps = 0;          // solid sub-steps over the run (most of any group) [-]
  long total_body_substeps = 0;     // the same summed over bodies: the work of the solid [-]
  long total_contact_inner_steps = 0;  // inner contact steps over the run, summed over groups [-]
  long total_pair_checks = 0;       // CDS pairs examined by the pair search over the run [-]
  // Work of the contact forces on all bodies since t = 0 [energy/length]: never positive for the
  // dissipative spring-dashpot law with walls at rest, apart from the integration error; a contact
  // that returns more energy than it received makes it grow (the guard in sim/checks/blow_up.cpp).
  double total_contact_work = 0.0;
};

// Storage the bodies' sub-steps reuse every step (sim/bodies/body_update.hpp, SolidStepInputs).
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
  // The velocity scale of the current state before the fluid is looked at: the fastest moving wall
  // or inflow (at its peak) and the fastest body point [length/time]. `ibms info` takes its CFL
  // limit and cell Reynolds number from it, and the guards' driving speed starts from it.
  double speed_scale() const { return std::max(boundary_speed_scale(scene_.walls), max_point_speed(bodies_)); }
  // Names of the pipeline stages this scene runs, in order (`ibms info` prints them): the
  // coupling's own stages and the contact model's constants.
  std::vector<std::string> stage_names() const;

  // The immersed-boundary coupling chosen from ibm.coupling (sim/coupling/coupling.hpp).
  Coupling& coupling() { return *coupling_; }
  const Coupling& coupling() const { return *coupling_; }
  // Bodies (docs/method.md §1), in scene order, and their markers and forces.
  std::vector<MassSpringBody>& bodies() { return bodies_; }
  const std::vector<MassSpringBody>& bodies() const { return bodies_; }
  const std::vector<SwellingSchedule>& swelling() const { return swelling_; }
  // Motion of the rigid and prescribed bodies (entry b unused for a mass_spring body).
  std::vector<RigidBody>& rigid() { return rigid_; }
  const std::vector<RigidBody>& rigid() const { return rigid_; }
  std::vector<BodyCoupling>& markers() { return markers_; }
  const std::vector<BodyCoupling>& markers() const { return markers_; }
  std::vector<std::vector<Vec2>>& contact_work() { return contact_work_; }
  KernelKind kernel() const { return kernel_; }
  const FluidBoundaries& boundaries() const { return fluid_solver_.boundaries(); }

  // The stages chosen when the Simulation is built.
  InnerFluidInertia inner_fluid_inertia() const { return inner_fluid_inertia_; }  // variant K or A
  const ContactForces& contact_forces() const { return contact_forces_; }  // the contact seam

  // DEM contacts (solver/contact), active when contact.stiffness > 0 or contact.model = "collision_time".
  bool has_contacts() const { return contact_model_.enabled(); }
  // The model of the latest step (collision_time: T_c of that step; for_fluid_step gives another dt's).
  const ContactModel& contact_model() const { return contact_model_; }
  // Pair search runs only with contacts and two or more bodies (docs/design.md §3: one body, no pair search).
  bool has_pair_search() const { return has_contacts() && bodies_.size() > 1; }
  // Which bodies sub-step together and at which contact bound (sim/bodies/substep_planning.hpp).
  const SubstepPlanner& substep_planner() const { return substep_planner_; }
  // The plan of the step of length dt, with the contact law of that step (collision_time:
  // T_c = collision_steps dt), which the contact seams read.
  SubstepGroups& substep_groups(double dt);

  // What the steps did, and the guards' scales and state (set when the Simulation is built).
  RunStatistics& stats() { return stats_; }
  const RunStatistics& stats() const { return stats_; }
  InstabilityBounds& instability() { return instability_; }
  const InstabilityBounds& instability() const { return instability_; }
  SolidSubstepWork& solid_work() { return solid_work_; }

  // The solid takes exactly n sub-steps per fluid step, ignoring its stability bound (n > 0: the
  // fixed-step runs of bench/bench_stability.cpp and the tests of the body guards); 0: automatic.
  void set_fixed_substeps(int n) { solid_work_.fixed_substeps = n; }
  int fixed_substeps() const { return solid_work_.fixed_substeps; }

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
  std::vector<BodyCoupling> markers_;
  std::unique_ptr<Coupling> coupling_;
  std::vector<std::vector<Vec2>> contact_work_;
  ContactModel contact_model_;
  WallBox contact_box_;
  InnerFluidInertia inner_fluid_inertia_ = nullptr;
  ContactForces contact_forces_ = no_contact_forces;
  // The contacts' inner loop (contact.time_stepping = "inner_loop"; empty: shared sub-steps).
  ContactInnerLoop contact_inner_loop_;
  SubstepPlanner substep_planner_;
  RunStatistics stats_;
  InstabilityBounds instability_;
  SolidSubstepWork solid_work_;
  void set_instability_bounds();
  void wire_contacts();
  // Adds one contact evaluation's time and figures to the timers and statistics (under a lock:
  // the groups' seams run on several threads at once).
  void record_contacts(double seconds, const ContactStats& found, long inner_steps);
};

// Builders shared with `ibms info` and tests.
Grid grid_from_scene(const Scene& scene);
FluidBoundaries boundaries_from_scene(const Scene& scene);


}  // namespace ibms
