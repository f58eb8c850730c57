// Sub-step bound of docs/method.md §5.1/§5.3. Departure from the plain Gershgorin bound of §5.3
// (omega^2 <= max_i sum_j |A_ij|, A = M^-1 K): that bound overestimates omega_max of the wheel
// by 1.54-1.60x (N_l = 20-70, hub mode), so a step at 3x the safe one would still be stable.
// Gershgorin applied to D^-1 |A| D is as rigorous for any positive diagonal D, and with D from
// a few power iterations on |A| it approaches the Perron root rho(|A|) >= rho(A)
// (Collatz-Wielandt: rho(|A|) <= max_r (|A| x)_r / x_r for every x > 0); for the wheel this is
// within 4-6 % of omega_max. Iteration 0 (x = 1) is the plain Gershgorin bound.
#include "solid/stable_substep.hpp"

#include "core/collatz_wielandt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ibms {
namespace {

using Block = std::array<double, 4>;  // symmetric 2x2 [xx, xy, yx, yy]

Block absolute(const Block& b) { return {std::abs(b[0]), std::abs(b[1]), std::abs(b[2]), std::abs(b[3])}; }

// Collatz-Wielandt bound of rho(|M^-1 A|) for the assembled stiffness-like matrix A with diagonal
// blocks diag[p] and off-diagonal blocks -element[s] between springs[s].i and springs[s].j.
double perron_bound(const MassSpringBody& body, const std::vector<Block>& diag,
                    const std::vector<Block>& element, std::vector<double>& x, std::vector<double>& y) {
  constexpr int n_iterations = 20;    // converged to 1e-4 for the wheel by iteration 10
  constexpr double positive_floor = 1e-12;  // keeps x > 0 so every iterate gives a valid bound
  // Evaluated for every wheel at every step: an iterate that tightens the bound by less than 1e-4
  // of it ends the iteration (the sub-step is at most about that much shorter than at 20 iterates).
  // At 1e-3 the contacts' inner loop and the shared sub-step parted by 1.18 % on a soft wheel's
  // bounce off a wall at e_D = 1 (test_contact_inner_loop asserts 1 %; 0.47 % at 20 iterates,
  // 0.88 % at 1e-4): that bounce's rebound is mostly the rim's vibration and moves with the step.
  constexpr double min_improvement = 1e-4;
  const int n = body.n_points();
  return collatz_wielandt_bound(2 * n, n_iterations, positive_floor, x, y,
                                [&](const std::vector<double>& v, std::vector<double>& w) {
    std::fill(w.begin(), w.end(), 0.0);
    for (int p = 0; p < n; ++p) {
      const Block a = absolute(diag[p]);
      w[2*p] += a[0]*v[2*p] + a[1]*v[2*p + 1];
      w[2*p + 1] += a[2]*v[2*p] + a[3]*v[2*p + 1];
    }
    for (std::size_t s = 0; s < body.springs.size(); ++s) {
      const Block a = absolute(element[s]);
      const int i = body.springs[s].i, j = body.springs[s].j;
      w[2*i] += a[0]*v[2*j] + a[1]*v[2*j + 1];
      w[2*i + 1] += a[2]*v[2*j] + a[3]*v[2*j + 1];
      w[2*j] += a[0]*v[2*i] + a[1]*v[2*i + 1];
      w[2*j + 1] += a[2]*v[2*i] + a[3]*v[2*i + 1];
    }
    for (int r = 0; r < 2*n; ++r) w[r] /= body.mass[r / 2];
  }, min_improvement);
}

}  // namespace

SpectralBounds spectral_bounds(const MassSpringBody& body) {
  SpectralWorkspace work;
  return spectral_bounds(body, work);
}

SpectralBounds spectral_bounds(const MassSpringBody& body, SpectralWorkspace& work) {
  const int n = body.n_points();
  const double s = body.length_scale();
  std::vector<Block>& stiffness_diag = work.stiffness_diag;
  std::vector<Block>& damping_diag = work.damping_diag;
  std::vector<Block>& stiffness_element = work.stiffness_element;
  std::vector<Block>& damping_element = work.damping_element;
  stiffness_diag.assign(n, Block{});
  damping_diag.assign(n, Block{});
  stiffness_element.clear();
  damping_element.clear();
  for (const Spring& spring : body.springs) {
    const auto& xi = body.position[spring.i];
    const auto& xj = body.position[spring.j];
    const double length = std::hypot(xj[0] - xi[0], xj[1] - xi[1]);
    if (!(length > 0.0)) throw std::invalid_argument("stable_substep: spring of zero length");
    const double ex = (xj[0] - xi[0]) / length, ey = (xj[1] - xi[1]) / length;
    // Tangent stiffness of a central spring: k e e^T + (T/L)(I - e e^T), T = k (L - s L0).
    const double geometric = spring.stiffness * (length - s*spring.natural_length0) / length;
    const Block k_block = {spring.stiffness*ex*ex + geometric*(1.0 - ex*ex),
                           (spring.stiffness - geometric)*ex*ey,
                           (spring.stiffness - geometric)*ex*ey,
                           spring.stiffness*ey*ey + geometric*(1.0 - ey*ey)};
    const Block c_block = {spring.damping*ex*ex, spring.damping*ex*ey, spring.damping*ex*ey,
                           spring.damping*ey*ey};
    stiffness_element.push_back(k_block);
    damping_element.push_back(c_block);
    for (int c = 0; c < 4; ++c) {
      stiffness_diag[spring.i][c] += k_block[c];
      stiffness_diag[spring.j][c] += k_block[c];
      damping_diag[spring.i][c] += c_block[c];
      damping_diag[spring.j][c] += c_block[c];
    }
  }
  return {perron_bound(body, stiffness_diag, stiffness_element, work.x, work.y),
          perron_bound(body, damping_diag, damping_element, work.x, work.y)};
}

double stable_substep(const MassSpringBody& body, double safety) {
  SpectralWorkspace work;
  return stable_substep(body, safety, work);
}

double stable_substep(const MassSpringBody& body, double safety, SpectralWorkspace& work) {
  if (body.springs.empty()) return std::numeric_limits<double>::infinity();
  const SpectralBounds bounds = spectral_bounds(body, work);
  const double gamma = bounds.damping_rate_max;
  const double omega_squared = bounds.omega_squared_max;
  if (gamma == 0.0 && omega_squared == 0.0) return std::numeric_limits<double>::infinity();
  // docs/method.md §5.1 limit 2 (sqrt(1 + zeta^2) - zeta)/omega, rationalised so omega = 0 is fine;
  // the largest gamma and omega may come from different modes, which only makes it smaller.
  return safety * 4.0 / (gamma + std::sqrt(gamma*gamma + 4.0*omega_squared));
}

}  // namespace ibms
