// Manufactured solution with no-slip walls on the unit square (docs/method.md §A10b, after Donea &
// Huerta 2003): psi = A a(x) a(y) g(t), a(s) = s^2 (1-s)^2, pressure P h(t) cos(pi x) cos(pi y)
// (zero mean). The forcing f = du/dt + (u.grad)u + grad p - nu lap u is derived in A10b; the
// pressure is kinematic. Derivation check: tools/derive_manufactured_forcing.py beside this file.
#pragma once
#include <cmath>

#include "core/constants.hpp"

namespace ibms::verification {

struct ManufacturedSolution {
  double amplitude = 80.0;   // A: max |u| about 1 [-]
  double pressure_amplitude = 1.0;  // P [-]
  double viscosity = 0.1;    // nu [-]
  bool steady = true;        // g = h = 1, else g(t) = cos(t), h(t) = cos(t)

  static double a(double s) { return s * s * (1 - s) * (1 - s); }
  static double a1(double s) { return 2 * s - 6 * s * s + 4 * s * s * s; }
  static double a2(double s) { return 2 - 12 * s + 12 * s * s; }
  static double a3(double s) { return 24 * s - 12; }
  double g(double t) const { return steady ? 1.0 : std::cos(t); }
  double g_dot(double t) const { return steady ? 0.0 : -std::sin(t); }
  double h(double t) const { return steady ? 1.0 : std::cos(t); }

  double u(double x, double y, double t) const { return amplitude * g(t) * a(x) * a1(y); }
  double v(double x, double y, double t) const { return -amplitude * g(t) * a1(x) * a(y); }
  double p(double x, double y, double t) const {
    return pressure_amplitude * h(t) * std::cos(pi * x) * std::cos(pi * y);
  }
  double force_x(double x, double y, double t) const {
    const double A = amplitude, gt = g(t);
    return A * g_dot(t) * a(x) * a1(y) +
           A * A * gt * gt * a(x) * a1(x) * (a1(y) * a1(y) - a(y) * a2(y)) -
           pressure_amplitude * h(t) * pi * std::sin(pi * x) * std::cos(pi * y) -
           viscosity * A * gt * (a2(x) * a1(y) + a(x) * a3(y));
  }
  double force_y(double x, double y, double t) const {
    const double A = amplitude, gt = g(t);
    return -A * g_dot(t) * a1(x) * a(y) +
           A * A * gt * gt * a(y) * a1(y) * (a1(x) * a1(x) - a(x) * a2(x)) -
           pressure_amplitude * h(t) * pi * std::cos(pi * x) * std::sin(pi * y) +
           viscosity * A * gt * (a3(x) * a(y) + a1(x) * a2(y));
  }
};

}  // namespace ibms::verification
