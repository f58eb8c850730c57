// Linear normal spring-dashpot contact force, docs/method.md §1.9; no tangential force.
#include "contact/normal_contact_law.hpp"

namespace ibms {

std::array<double, 2> contact_force_on_first(const ContactLaw& law, const ContactKinematics& contact) {
  const std::array<double, 2>& n = contact.normal;
  const double normal_rate = contact.relative_velocity[0]*n[0] + contact.relative_velocity[1]*n[1];
  // F_i = -(k delta - c v_n) n: approach (v_n < 0) adds to the repulsion.
  const double push = law.stiffness*contact.overlap - law.damping*normal_rate;
  return {-push * n[0], -push * n[1]};
}

}  // namespace ibms
