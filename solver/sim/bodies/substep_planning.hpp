// Sub-step planning (docs/method.md §5.3): before the bodies advance, which of them may touch one
// another or a wall within the fluid step, and so which groups sub-step together and which contact
// sub-step bound each group takes. The planner reads the bodies, their hydrodynamic forces and the
// contact law of the Simulation that owns it; it keeps the scratch of the group search, so that
// planning a step allocates nothing once the sizes are known.
#pragma once
#include <cstddef>
#include <vector>

#include "contact/contact_model.hpp"
#include "scene/scene.hpp"
#include "sim/coupling/body_coupling.hpp"
#include "sim/bodies/body_update.hpp"
#include "solid/mass_spring_body.hpp"

namespace ibms {

class SubstepPlanner {
 public:
  // What the plans read, owned by the Simulation and outliving the planner.
  SubstepPlanner(const Scene& scene, const std::vector<MassSpringBody>& bodies,
                 const std::vector<BodyCoupling>& coupling, const ContactModel& contact_model,
                 const WallBox& contact_box, const ContactInnerLoop& contact_inner_loop);

  // Whether a contact can be under way within the next step of length dt (contact/contact_model.hpp);
  // false without contacts. Only then does the contact sub-step bound apply.
  bool contact_possible(double dt) const;
  // The global bound (run.solid_substeps = "global"): the contact sub-step of all bodies if any
  // contact is possible.
  double global_contact_limit(double dt) const;
  // How the bodies sub-step in a step of length dt (sim/bodies/body_update.hpp), into `groups`: the
  // contact groups with the contact sub-step bound of each group that may touch something; with
  // run.solid_substeps = "global", no groups (one group, bound global_contact_limit(dt)).
  void plan(double dt, SubstepGroups& groups) const;
  // The same into the planner's own groups: the plan the step runs, which advance_bodies fills
  // with the sub-steps each body took.
  SubstepGroups& plan_step(double dt);
  // Sub-steps body b took in the latest step (0 before the first).
  int body_substeps(std::size_t b) const {
    return b < step_groups_.substeps_of_body.size() ? step_groups_.substeps_of_body[b] : 0;
  }

 private:
  const Scene& scene_;
  const std::vector<MassSpringBody>& bodies_;
  const std::vector<BodyCoupling>& coupling_;
  const ContactModel& contact_model_;
  const WallBox& contact_box_;
  const ContactInnerLoop& contact_inner_loop_;
  mutable std::vector<double> contact_reach_;  // scratch of find_groups, one entry per body
  mutable ContactGroups contact_groups_;       // scratch of contact_possible and plan
  SubstepGroups step_groups_;
  void find_groups(double dt) const;           // contact_groups_ for a step of length dt
};

}  // namespace ibms
