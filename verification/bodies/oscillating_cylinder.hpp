// The unsteady Stokes flow around a circular cylinder oscillating with small amplitude in fluid at
// rest (Stokes 1851; Landau & Lifshitz, Fluid Mechanics, §24 problem 5): for the velocity
// U(t) = Re(U^ e^{i w t}) the force of the fluid on the cylinder (radius a, per unit depth) is
//     F^ = -i w m_f U^ (1 + k),   k = 4 K_1(s) / (s K_0(s)),   s = a sqrt(i w / nu),
// m_f = rho pi a^2 the displaced fluid's mass. In the time domain
//     F = -m_f (1 + Re k) dU/dt + m_f w Im(k) U:
// an added-mass part (coefficient 1 + Re k, 1 for potential flow) and a Stokes-drag part.
// K_0, K_1 of the complex argument (arg s = pi / 4) from K_v(z) = int_0^inf exp(-z cosh t) cosh(v t) dt
// (Re z > 0; Abramowitz & Stegun 9.6.24), by the trapezoidal rule, spectrally accurate for this
// analytic, doubly exponentially decaying integrand.
#pragma once
#include <cmath>
#include <complex>

namespace ibms::test {

inline std::complex<double> bessel_k(int order, std::complex<double> z) {
  // exp(-Re z cosh t) < 1e-300 beyond t_max.
  const double t_max = std::acosh(std::max(2.0, 700.0 / z.real()));
  const int n = 20000;
  const double dt = t_max / n;
  std::complex<double> sum = 0.5 * std::exp(-z);  // t = 0, weight 1/2 (cosh 0 = 1)
  for (int k = 1; k <= n; ++k) {
    const double t = k * dt;
    sum += std::exp(-z * std::cosh(t)) * std::cosh(order * t);
  }
  return sum * dt;
}

struct StokesCylinderForce {
  double added_mass_coefficient = 0.0;  // 1 + Re k: F_a = -C_m m_f dU/dt [-]
  double drag_coefficient = 0.0;        // -w Im k: F_d = -C_d m_f U [1/time]
};

inline StokesCylinderForce stokes_cylinder_force(double radius, double omega, double nu) {
  const std::complex<double> s = radius * std::sqrt(std::complex<double>(0.0, omega / nu));
  const std::complex<double> k = 4.0 * bessel_k(1, s) / (s * bessel_k(0, s));
  return {1.0 + k.real(), -omega * k.imag()};
}

}  // namespace ibms::test
