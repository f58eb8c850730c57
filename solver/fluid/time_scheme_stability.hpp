// Von Neumann amplification of the fluid's time scheme (docs/fluid-stability.md): AB2 convection
// and Crank-Nicolson diffusion with second-order central differences, for one Fourier mode of
// wave angle theta = k h under a constant velocity U. With C = U dt / h (CFL number) and
// D = nu dt / h^2 (viscous number), a = -i C sin(theta), b = -2 D (1 - cos(theta)), the step
//   u^{n+1} - u^n = (3/2) a u^n - (1/2) a u^{n-1} + (b/2)(u^{n+1} + u^n)
// multiplies the mode by a root G of (1 - b/2) G^2 - (1 + 3a/2 + b/2) G + a/2 = 0.
// reports/fluid_stability_theory.py is the same formula (draws the boundary on the maps).
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>

#include "core/constants.hpp"

namespace ibms {

// The larger |G| of the two roots at one wave angle theta [rad] [-].
inline double ab2_cn_amplification(double cfl, double viscous_number, double theta) {
  using complex = std::complex<double>;
  const complex a(0.0, -cfl * std::sin(theta));
  const double b = -2.0 * viscous_number * (1.0 - std::cos(theta));
  const complex quadratic(1.0 - 0.5 * b), linear = -(1.0 + 1.5 * a + 0.5 * b), constant = 0.5 * a;
  const complex root = std::sqrt(linear * linear - 4.0 * quadratic * constant);
  return std::max(std::abs((-linear + root) / (2.0 * quadratic)), std::abs((-linear - root) / (2.0 * quadratic)));
}

// max over theta in [0, pi] of ab2_cn_amplification (sampled at n_angles + 1 angles) [-].
inline double ab2_cn_max_amplification(double cfl, double viscous_number, int n_angles = 2000) {
  double largest = 0.0;
  for (int k = 0; k <= n_angles; ++k)
    largest = std::max(largest, ab2_cn_amplification(cfl, viscous_number, pi * k / n_angles));
  return largest;
}

// Largest CFL number C stable at cell Reynolds number Re_h = U h / nu, i.e. with D = C / Re_h
// (bisection; the stable C at one Re_h form one interval [0, limit]: docs/fluid-stability.md) [-].
inline double ab2_cn_cfl_limit(double cell_reynolds) {
  double low = 0.0, high = 8.0;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (low + high);
    if (ab2_cn_max_amplification(mid, mid / cell_reynolds, /*n_angles=*/500) > 1.0 + 1e-12) high = mid;
    else low = mid;
  }
  return low;
}

}  // namespace ibms
