// Sub-step planning (substep_planning.hpp): the contact groups of a step and their sub-step bounds.
#include "sim/bodies/substep_planning.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace ibms {

SubstepPlanner::SubstepPlanner(const Scene& scene, const std::vector<MassSpringBody>& bodies,
                               const std::vector<BodyCoupling>& coupling, const ContactModel& contact_model,
                               const WallBox& contact_box, const ContactInnerLoop& contact_inner_loop)
    : scene_(scene),
      bodies_(bodies),
      coupling_(coupling),
      contact_model_(contact_model),
      contact_box_(contact_box),
      contact_inner_loop_(contact_inner_loop) {}

bool SubstepPlanner::contact_possible(double dt) const {
  if (!contact_model_.enabled()) return false;
  find_groups(dt);
  return contact_groups_.any_contact();
}

double SubstepPlanner::global_contact_limit(double dt) const {
  return contact_possible(dt) ? contact_substep(contact_model_.for_fluid_step(dt), bodies_) : HUGE_VAL;
}

SubstepGroups& SubstepPlanner::plan_step(double dt) {
  plan(dt, step_groups_);
  return step_groups_;
}

void SubstepPlanner::plan(double dt, SubstepGroups& groups) const {
  if (static_cast<bool>(groups.inner_loop) != static_cast<bool>(contact_inner_loop_)) groups.inner_loop = contact_inner_loop_;
  groups.outer_step_fraction = contact_model_.outer_step_fraction;
  if (scene_.run.solid_substeps == RunSpec::SolidSubsteps::global) {
    groups.group_of.clear();
    return;
  }
  find_groups(dt);
  groups.group_of.assign(contact_groups_.group_of.begin(), contact_groups_.group_of.end());
  groups.max_substep.assign(contact_groups_.n_groups, HUGE_VAL);
  groups.list_members();
  for (int g = 0; g < contact_groups_.n_groups; ++g)
    if (contact_groups_.may_touch[g])
      groups.max_substep[g] = contact_substep(contact_model_.for_fluid_step(dt), bodies_, groups.group_members(g));
}

void SubstepPlanner::find_groups(double dt) const {
  // Extra reach of each body within dt (contact/contact_model.hpp), all bounds doubled:
  //   travel from its acceleration a_b dt^2 (the exact 1/2 a dt^2 doubled), with
  //   a_b = |F_hydro| / m + |1 - rho_f/rho_s| |g| (frozen over the step; springs and contacts act
  //   inside the body and between bodies already touching, which the gap test catches), and for a
  //   prescribed body the largest acceleration of its motion |A| w^2 + (R)(|Theta| w^2 + Omega^2 + ...);
  //   and swelling: the radius grows by at most rate dt / 2 (and the CDS radius with it).
  const double gravity = std::hypot(scene_.fluid.gravity[0], scene_.fluid.gravity[1]);
  contact_reach_.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const MassSpringBody& body = bodies_[b];
    const BodySpec& spec = scene_.bodies[b];
    double acceleration = 0.0;
    if (body.kind == BodyKind::prescribed) {
      const double w = spec.oscillation_period > 0 ? 2 * pi / spec.oscillation_period : 0.0;
      const double radius = 0.5 * body.diameter;
      const double omega_max = std::abs(spec.angular_velocity) + std::abs(spec.angle_amplitude) * w;
      acceleration = std::hypot(spec.oscillation_amplitude[0], spec.oscillation_amplitude[1]) * w * w +
                     radius * (std::abs(spec.angle_amplitude) * w * w + omega_max * omega_max);
    } else {
      const Vec2& f = coupling_[b].hydrodynamic_force;
      acceleration = std::hypot(f[0], f[1]) / body.total_mass() +
                     std::abs(1.0 - scene_.fluid.density / body.density) * gravity;
    }
    const double growth = spec.swelling.enabled ? spec.swelling.rate * dt * (1.0 + contact_model_.cds_radius_fraction) : 0.0;
    contact_reach_[b] = acceleration * dt * dt + growth;
  }
  find_contact_groups(contact_model_, bodies_, contact_box_, dt, contact_reach_, contact_groups_);
}

}  // namespace ibms
