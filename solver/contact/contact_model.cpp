// Contact parameters, CDS radius and contact sub-step bound, METHOD.md §1.9, §5.1 and A8.
#include "contact/contact_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solid/spring_dashpot.hpp"

namespace ibms {

ContactModel::ContactModel(const ContactSpec& spec)
    : stiffness(spec.stiffness),
      restitution_coefficient(spec.restitution_coefficient),
      cds_radius(spec.cds_radius),
      cds_radius_fraction(spec.cds_radius_fraction),
      walls(spec.walls) {
  if (!(stiffness >= 0.0)) throw std::invalid_argument("contact: stiffness must be >= 0");
  if (!(restitution_coefficient > 0.0 && restitution_coefficient <= 1.0))
    throw std::invalid_argument("contact: restitution_coefficient must be in (0, 1]");
  if (!(steps_per_contact >= 1.0) || !(active_pairs_safety >= 1.0))
    throw std::invalid_argument("contact: steps_per_contact and active_pairs_safety must be >= 1");
  if (!(cds_radius >= 0.0) || !(cds_radius_fraction >= 0.0))
    throw std::invalid_argument("contact: cds_radius and cds_radius_fraction must be >= 0");
  if (enabled() && cds_radius == 0.0 && cds_radius_fraction == 0.0)
    throw std::invalid_argument("contact: stiffness > 0 needs cds_radius or cds_radius_fraction");
}

double ContactModel::cds_radius_of(const MassSpringBody& body) const {
  return cds_radius > 0.0 ? cds_radius : cds_radius_fraction * body.diameter;
}

double contact_substep(const ContactModel& model, const std::vector<MassSpringBody>& bodies) {
  constexpr double dashpot_safety = 0.5;      // METHOD.md §5.3 safety factor on a stability limit
  if (!model.enabled() || bodies.empty()) return std::numeric_limits<double>::infinity();
  double lightest_point = std::numeric_limits<double>::infinity();
  double heaviest_body = 0.0;
  for (const MassSpringBody& body : bodies) {
    for (int k = 0; k < body.n_surface; ++k) lightest_point = std::min(lightest_point, body.mass[k]);
    heaviest_body = std::max(heaviest_body, body.total_mass());
  }
  // Two equal lightest points in a pair have m_eff = m_p / 2; against a wall m_eff = m_p.
  const double m_eff = bodies.size() > 1 ? 0.5 * lightest_point : lightest_point;
  const double n_active = model.active_pairs_safety;
  const double stiffness = n_active * model.stiffness;
  // Damping of n_active pairs as add_contact_forces builds it; the heaviest body pair gives the
  // largest c in the body convention.
  const double damping_mass =
      model.effective_mass == ContactEffectiveMass::body ? heaviest_body : m_eff;
  const double per_pair_stiffness =
      model.share_damping_among_active_pairs ? model.stiffness / n_active : model.stiffness;
  const double total_damping =
      n_active * damping_from_restitution(model.restitution_coefficient, damping_mass, per_pair_stiffness);
  // t_c = sqrt(m_eff / k) sqrt(pi^2 + ln^2 e) (A8), here from the undamped point oscillator
  // (the shortest duration; damping lengthens it).
  const double duration = contact_duration(m_eff, stiffness, /*damping=*/0.0);
  double substep = duration / model.steps_per_contact;
  if (total_damping > 0.0)
    substep = std::min(substep, dashpot_safety * 2.0 * lightest_point / total_damping);
  return substep;
}

}  // namespace ibms
