// The inner step of the contacts' inner loop from the listed pairs (InnerStepBound::listed_pairs,
// contact_subcycle.hpp): steps_per_contact steps per contact duration of the fastest mode the
// listed pairs and walls can form.
#include "contact/contact_subcycle.hpp"

#include <cmath>

#include "core/collatz_wielandt.hpp"
#include "core/constants.hpp"

namespace ibms {

double ContactSubcycler::listed_pairs_step(const ContactModel& model) {
  // The contact modes of the listed pairs solve M x'' + C x' + K x = 0. Their rates |lambda| are
  // at most sqrt(omega_K^2) + omega_C with omega_K^2 and omega_C the largest eigenvalues of
  // M^-1/2 K M^-1/2 and M^-1/2 C M^-1/2 (one oscillator: |lambda| <= c / m + sqrt(k / m)). Each is
  // at most the spectral radius of its matrix of 2x2 block norms (||A|| <= ||B|| for a symmetric A
  // and its block-norm matrix B): diagonal sum over the candidate's pairs and walls of k / m_i (a
  // pair's k n n^T has norm k), off-diagonal k / sqrt(m_i m_j), and the same with the pairs'
  // dashpots c (unshared: an upper bound while S >= 1, i.e. unless two pairs of one body pair have
  // normals more than 90 degrees apart, which convex rims do not form; the dashpot bound of
  // contact_substep assumes the same); collatz_wielandt_bound bounds that radius from above.
  // One undamped pair of masses m_a, m_b gives k / m_eff exactly: A8's t_c.
  if (points_.empty()) return HUGE_VAL;
  stiffness_sum_.assign(points_.size(), 0.0);
  damping_sum_.assign(points_.size(), 0.0);
  const double* const inverse_mass = points_.inverse_mass.data();
  bool damped = false;
  for (const Pair& pair : pairs_) {
    stiffness_sum_[pair.a] += pair.stiffness * inverse_mass[pair.a];
    stiffness_sum_[pair.b] += pair.stiffness * inverse_mass[pair.b];
    damping_sum_[pair.a] += pair.damping * inverse_mass[pair.a];
    damping_sum_[pair.b] += pair.damping * inverse_mass[pair.b];
    damped = damped || pair.damping > 0.0;
  }
  for (const Wall& wall : walls_) {
    stiffness_sum_[wall.a] += wall.stiffness * inverse_mass[wall.a];
    damping_sum_[wall.a] += wall.damping * inverse_mass[wall.a];
    damped = damped || wall.damping > 0.0;
  }
  // The block-norm matrix with the given diagonal and, for each listed pair p = (a, b), the entry
  // w_p / sqrt(m_a m_b), w_p the pair's stiffness (damping: its dashpot); x stays > 0 (every
  // diagonal is > 0), so no floor.
  constexpr int iterations = 8;
  const auto radius = [&](const std::vector<double>& diagonal, bool damping) {
    return collatz_wielandt_bound(points_.size(), iterations, /*floor=*/0.0, perron_x_, perron_y_,
                                  [&](const std::vector<double>& x, std::vector<double>& y) {
      for (std::size_t i = 0; i < x.size(); ++i) y[i] = diagonal[i] * x[i];
      for (const Pair& pair : pairs_) {
        const double w = (damping ? pair.damping : pair.stiffness) * std::sqrt(inverse_mass[pair.a] * inverse_mass[pair.b]);
        y[pair.a] += w * x[pair.b];
        y[pair.b] += w * x[pair.a];
      }
    });
  };
  const double omega_k = std::sqrt(radius(stiffness_sum_, false));
  const double omega_c = damped ? radius(damping_sum_, true) : 0.0;
  // t_c = pi / |lambda|, steps_per_contact steps in it.
  const double rate = omega_k + omega_c;
  return rate > 0.0 ? pi / (model.steps_per_contact * rate) : HUGE_VAL;
}

}  // namespace ibms
