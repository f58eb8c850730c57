// Von Neumann amplification of the fluid's time scheme (docs/fluid-stability.md): AB2 convection
// and Crank-Nicolson diffusion with second-order central differences, for one Fourier mode of
// wave angle theta = k h under a constant velocity U. With C = U dt / h (CFL number) and
// D = nu dt / h^2 (viscous number), a = -i C sin(theta), b = -2 D (1 - cos(theta)), the step
//   u^{n+1} - u^n = (3/2) a u^n - (1/2) a u^{n-1} + (b/2)(u^{n+1} + u^n)
// multiplies the mode by a root G of (1 - b/2) G^2 - (1 + 3a/2 + b/2) G + a/2 = 0.
// With the upwind-biased face values of the kappa family (convection_upwind_biased; kappa = 1 is
// the central mean) a = C s(theta) with s of convective_symbol.
// reports/fluid_stability_theory.py is the same formula (draws the boundary on the maps).
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>

#include "core/constants.hpp"

namespace ibms {

// a / C of the face values of the kappa family for U > 0 at wave angle theta: the face value
// q_f = q_up + (1 - kappa)/4 (q_up - q_upup) + (1 + kappa)/4 (q_down - q_up) of the mode e^{i j theta}
// is F q_j with F = 1 + (1 - kappa)/4 (1 - e^{-i theta}) + (1 + kappa)/4 (e^{i theta} - 1), and the
// flux difference gives s = -F (1 - e^{-i theta}); kappa = 1: -i sin(theta) [-].
inline std::complex<double> convective_symbol(double theta, double kappa) {
  if (kappa == 1.0) return {0.0, -std::sin(theta)};
  const std::complex<double> ahead = std::polar(1.0, theta), behind = std::polar(1.0, -theta);
  const std::complex<double> face = 1.0 + 0.25 * (1.0 - kappa) * (1.0 - behind) + 0.25 * (1.0 + kappa) * (ahead - 1.0);
  return -face * (1.0 - behind);
}

// The larger |G| of the two roots at one wave angle theta [rad] [-].
inline double ab2_cn_amplification(double cfl, double viscous_number, double theta, double kappa = 1.0) {
  using complex = std::complex<double>;
  const complex a = cfl * convective_symbol(theta, kappa);
  const double b = -2.0 * viscous_number * (1.0 - std::cos(theta));
  const complex quadratic(1.0 - 0.5 * b), linear = -(1.0 + 1.5 * a + 0.5 * b), constant = 0.5 * a;
  const complex root = std::sqrt(linear * linear - 4.0 * quadratic * constant);
  return std::max(std::abs((-linear + root) / (2.0 * quadratic)), std::abs((-linear - root) / (2.0 * quadratic)));
}

// max over theta in [0, pi] of ab2_cn_amplification (sampled at n_angles + 1 angles) [-].
inline double ab2_cn_max_amplification(double cfl, double viscous_number, int n_angles = 2000, double kappa = 1.0) {
  double largest = 0.0;
  for (int k = 0; k <= n_angles; ++k)
    largest = std::max(largest, ab2_cn_amplification(cfl, viscous_number, pi * k / n_angles, kappa));
  return largest;
}

// Largest CFL number C stable at cell Reynolds number Re_h = U h / nu, i.e. with D = C / Re_h
// (bisection; the stable C at one Re_h form one interval [0, limit]: docs/fluid-stability.md) [-].
inline double ab2_cn_cfl_limit(double cell_reynolds, double kappa = 1.0) {
  double low = 0.0, high = 8.0;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (low + high);
    if (ab2_cn_max_amplification(mid, mid / cell_reynolds, /*n_angles=*/500, kappa) > 1.0 + 1e-12) high = mid;
    else low = mid;
  }
  return low;
}

}  // namespace ibms
