// The solid part of the step (docs/method.md §5.3, §7 step 6), multi-rate: the bodies are
// split into groups that cannot touch one another within the step (contact_model.hpp,
// find_contact_groups); each group takes n_sub = ceil(dt / dt_s) symplectic-Euler sub-steps, dt_s
// the smallest stable sub-step of its members (§5.1, safety 0.5) and, if the group may touch
// something, the contact sub-step of its members. Bodies in contact share their sub-steps, so pair
// forces stay equal and opposite. A mass-spring body whose springs would need more than
// implicit_springs_above_substeps explicit sub-steps (or spring_integrator = "implicit") takes
// linearly implicit Euler steps instead (solid/implicit_euler.hpp) and sets no sub-step of its own.
// Each sub-step re-evaluates springs and dashpots, buoyancy-corrected gravity F_e = M (1 - rho_f/rho_s) g (§1.7
// step 5, §2.6), contact forces (the hook below) and the swelling law (natural lengths and
// masses, §1.8) re-evaluated every sub-step, while the fluid reaction F_f and the inner-fluid
// force F_int stay frozen at their values from the projection.
#pragma once
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "sim/coupling/body_coupling.hpp"
#include "contact/contact_model.hpp"
#include "solid/implicit_euler.hpp"
#include "solid/rigid_motion.hpp"
#include "solid/stable_substep.hpp"

namespace ibms {

// Contact seam: adds the contact force on every point of every body [force/length] at `time`
// (forces[b][p], sized like the bodies, zeroed by the caller). Called once per sub-step.
// The default is no_contact_forces; solver/contact provides the DEM version.
// members: the contact group being sub-stepped; only contacts among its bodies and with the walls.
// Called concurrently for different groups (advance_bodies runs groups on several threads): it
// must only write the forces of its members and guard any shared state.
using ContactForces = std::function<void(const std::vector<MassSpringBody>& bodies, const BodySet& members,
                                         double time, std::vector<std::vector<Vec2>>& forces)>;
void no_contact_forces(const std::vector<MassSpringBody>& bodies, const BodySet& members, double time,
                       std::vector<std::vector<Vec2>>& forces);

// Inner-loop seam (contact/contact_subcycle.hpp): advances the members' points over dt_outer with the
// DEM contacts re-evaluated in n_inner inner steps on the points near a contact only, the springs
// and frozen_force[b][p] (fluid, inner fluid, buoyant gravity) held over dt_outer; returns the work
// of the contact forces [energy/length]. Called concurrently for different groups, as
// ContactForces. Empty: every group takes the shared sub-step.
// continues: the call follows the previous outer step of the same group within the fluid step;
// diameter_rate: dD/dt of each body over the outer step (swelling; the members' entries).
using ContactInnerLoop = std::function<double(std::vector<MassSpringBody>& bodies, const BodySet& members,
                                              double dt_outer, int n_inner,
                                              const std::vector<std::vector<Vec2>>& frozen_force, bool continues,
                                              const std::vector<double>& diameter_rate)>;

// Sets every body's diameter (natural lengths) and masses (constant density) to D(time).
void apply_swelling_schedules(const std::vector<SwellingSchedule>& swelling, double time,
                              std::vector<MassSpringBody>& bodies);

// How the bodies are sub-stepped in one fluid step: group_of[b] the group of body b (bodies of one
// group advance together), max_substep[g] the contact sub-step bound of group g (HUGE_VAL when it
// cannot touch anything). Empty group_of: all bodies one group bounded by SolidStepInputs::max_substep
// (the global sub-step, run.solid_substeps = "global").
// With inner_loop set, a group that may touch something and holds only mass_spring bodies with
// explicit springs takes its springs' sub-step (outer) and the contact sub-step only in the inner
// loop over the points near a contact (multiple time stepping, contact_subcycle.hpp).
struct SubstepGroups {
  std::vector<int> group_of;
  std::vector<double> max_substep;
  ContactInnerLoop inner_loop;        // empty: the shared sub-step for every group
  // The inner loop's outer step as a fraction of the group's springs' stable sub-step
  // (ContactModel::outer_step_fraction) [-].
  double outer_step_fraction = inner_loop_outer_fraction;
  std::vector<int> group_inner_substeps;  // out: inner steps per outer sub-step of each group (0: shared)
  std::vector<int> member_start;  // scratch: group g's bodies are member_list[member_start[g] ..
  std::vector<int> member_list;   //   member_start[g + 1]), ascending (list_members)
  // Lists each group's bodies from group_of, in O(bodies + groups): a group's loops then visit its
  // own bodies only.
  void list_members();
  BodySet group_members(int g) const {
    return BodySet::group(member_list.data() + member_start[g],
                          static_cast<std::size_t>(member_start[g + 1] - member_start[g]));
  }
  std::vector<int> substeps_of_body;  // out: the sub-steps body b took in the latest step
  std::vector<char> implicit_of_body; // out: body b's springs took implicit steps in the latest step
  std::vector<int> group_substeps;    // scratch: sub-steps of each group in the latest step
  std::vector<double> group_work;     // scratch: contact work of each group
  std::vector<double> diameter_rate;  // scratch: dD/dt of each body over its outer sub-step
  double contact_work = 0.0;          // out: work of all contact forces on all bodies in the latest step
                                      // [energy/length]; <= 0 for a dissipative contact law, walls at rest
};

// spring_integrator = "auto" chooses the implicit step when the explicit one would need more than
// this many sub-steps per fluid step: the springs' fastest period is then below dt / 25 (the
// explicit limit is ~ 1 / omega_max with safety 0.5), far from what the fluid step resolves, and the
// implicit step's damping of such modes is what a stiff body should show. Below it the explicit
// sub-steps are cheap and keep the elastic vibrations.
inline constexpr double implicit_springs_above_substeps = 50.0;
// Whether body b's springs take the implicit step in a fluid step of length dt, given their
// explicit stable sub-step (only mass_spring bodies with springs can).
bool uses_implicit_springs(const MassSpringBody& body, double dt, double spring_substep);
// How a body's springs are stepped in a fluid step of length dt (the run's rule, which `ibms info`
// prints): implicit (forced by spring_integrator, or chosen by uses_implicit_springs), or explicit
// in sub-steps of at most `substep`, the springs' stable sub-step (safety 0.5; the spectral bound
// is computed only where it decides something). substep is infinity when implicit.
struct SpringStepping {
  bool implicit = false;
  double substep = HUGE_VAL;  // [time]
};
SpringStepping spring_stepping(const MassSpringBody& body, double dt, SpectralWorkspace& scratch);

// What advance_bodies did: the most sub-steps of any group, and the sub-steps summed over bodies
// (the work of the springs: with one group, n_bodies * max_substeps).
struct SolidStepCount {
  int max_substeps = 0;
  long body_substeps = 0;
};
struct SolidStepInputs {
  double time = 0.0;                 // t^n [time]
  double dt = 0.0;                   // fluid step [time]
  double fluid_density = 0.0;        // rho_f [mass/length^3]
  Vec2 gravity{0.0, 0.0};            // g [length/time^2]
  double max_substep = HUGE_VAL;     // further sub-step bound of the global mode (no groups) [time]
  int fixed_substeps = 0;            // > 0: exactly this many sub-steps, no stability bound (stability studies)
  SpectralWorkspace* spectral_workspace = nullptr;  // scratch of the sub-step bound (null: allocates)
  std::vector<ImplicitSpringSystem>* implicit_systems = nullptr;  // per body, reused (null: allocates)
};

// Advances all bodies from t^n to t^n + dt, group by group (groups.group_of; empty: one group).
// Each sub-step
// moves each body by its kind (docs/design.md §11): mass_spring by symplectic Euler of its points;
// rigid by Newton-Euler with the total hydrodynamic force and torque (frozen over the step),
// the contact forces summed to force and torque about X_c, and m (1 - rho_f/rho_s) g; prescribed
// to its scene motion at the sub-step's end. rigid[b] holds the motion of rigid and prescribed
// bodies (unused for mass_spring). contact_work is scratch (resized once).
// The sub-steps advance_bodies takes with these groups (it plans with this): fills
// groups.substeps_of_body, groups.group_substeps and groups.implicit_of_body.
SolidStepCount count_substeps(const SolidStepInputs& in, SubstepGroups& groups,
                              const std::vector<MassSpringBody>& bodies);

SolidStepCount advance_bodies(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                              const ContactForces& contact_forces, SubstepGroups& groups,
                              std::vector<BodyCoupling>& coupling, std::vector<std::vector<Vec2>>& contact_work,
                              std::vector<RigidBody>& rigid, std::vector<MassSpringBody>& bodies);

}  // namespace ibms
