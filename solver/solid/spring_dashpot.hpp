// Linear spring-dashpot relations (docs/method.md §1.5 and appendix A8), shared by the body springs
// and the DEM contacts: for effective mass m_eff and stiffness k,
//   zeta = -ln e / sqrt(pi^2 + ln^2 e),  c = 2 zeta sqrt(m_eff k),
//   t_c = pi / omega_d = sqrt(m_eff/k) sqrt(pi^2 + ln^2 e),  delta_max ~ v0 sqrt(m_eff/k).
// Units per unit depth: k [force/length^2], c [force time/length^2], m_eff [mass/length].
#pragma once
#include <cmath>

namespace ibms {

// Damping ratio zeta [-] giving restitution e in (0, 1]; e = 1 -> 0.
double damping_ratio_from_restitution(double restitution);

// Dashpot constant c = 2 zeta sqrt(m_eff k) (docs/method.md §1.5, A8).
double damping_from_restitution(double restitution, double m_eff, double stiffness);
// The same from zeta = damping_ratio_from_restitution(e), for callers that build many pairs.
inline double dashpot_constant(double damping_ratio, double m_eff, double stiffness) {
  return 2.0 * damping_ratio * std::sqrt(m_eff * stiffness);
}

// Inverse: e = exp(-pi zeta / sqrt(1 - zeta^2)) with zeta = c / (2 sqrt(m_eff k)); 0 if zeta >= 1.
double restitution_from_damping(double damping, double m_eff, double stiffness);

// Contact duration t_c = pi / sqrt(k/m_eff - (c/(2 m_eff))^2) [time] (A8); infinity if overdamped.
double contact_duration(double m_eff, double stiffness, double damping);

// Undamped estimate of the largest overlap for impact speed v0: v0 sqrt(m_eff/k) [length] (A8).
double max_overlap_estimate(double impact_speed, double m_eff, double stiffness);

}  // namespace ibms
