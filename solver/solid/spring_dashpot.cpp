// Spring-dashpot restitution, damping and contact-time relations, docs/method.md §1.5, A8.
#include "solid/spring_dashpot.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/constants.hpp"

namespace ibms {

double damping_ratio_from_restitution(double restitution) {
  if (!(restitution > 0.0 && restitution <= 1.0))
    throw std::invalid_argument("restitution coefficient must be in (0, 1]");
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(pi*pi + log_e*log_e);
}

double damping_from_restitution(double restitution, double m_eff, double stiffness) {
  if (!(m_eff > 0.0) || !(stiffness >= 0.0))
    throw std::invalid_argument("damping_from_restitution: need m_eff > 0 and stiffness >= 0");
  return dashpot_constant(damping_ratio_from_restitution(restitution), m_eff, stiffness);
}

double restitution_from_damping(double damping, double m_eff, double stiffness) {
  const double zeta = damping / (2.0 * std::sqrt(m_eff * stiffness));
  if (zeta >= 1.0) return 0.0;  // overdamped: the contact never separates with speed
  return std::exp(-pi * zeta / std::sqrt(1.0 - zeta*zeta));
}

double contact_duration(double m_eff, double stiffness, double damping) {
  const double half_rate = damping / (2.0 * m_eff);
  const double omega_d_squared = stiffness / m_eff - half_rate*half_rate;
  if (!(omega_d_squared > 0.0)) return std::numeric_limits<double>::infinity();
  return pi / std::sqrt(omega_d_squared);
}

double max_overlap_estimate(double impact_speed, double m_eff, double stiffness) {
  return std::abs(impact_speed) * std::sqrt(m_eff / stiffness);
}

}  // namespace ibms
