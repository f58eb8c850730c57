// Manufactured solution for a box with an inflow side (x = 0), an outflow side (x = 1) and walls
// (y = 0, 1). Stream function psi = A c(t) g(x) h(y) with
//   h(y) = sin^2(pi y)                 (u = v = 0 on the walls: h = h' = 0 at y = 0, 1),
//   g(x) = (1 - x)^3 (1 + x)           (g'(1) = g''(1) = 0: du/dx = dv/dx = 0 at the outflow),
// u = psi_y = A c g h', v = -psi_x = -A c g' h, and the kinematic pressure
//   p = P q(t) (1 - x)(2 + x) cos(pi y)   (p = 0 at the outflow, dp/dy = 0 on the walls, and a
//                                          non-zero dp/dx = -P q cos(pi y) at the inflow).
// The inflow data (both components) come from the exact solution; the outflow conditions of the
// solver (zero normal gradient of velocity, p = 0) hold exactly. Forcing f = du/dt + (u.grad)u +
// grad p - nu lap u from the derivatives below (each written out, checked by finite differences
// in test_open_boundaries.cpp).
#pragma once
#include <cmath>

#include "core/constants.hpp"

namespace ibms::verification {

struct ChannelSolution {
  double amplitude = 0.3;           // A: max |u| about 0.94 [-]
  double pressure_amplitude = 0.5;  // P [-]
  double viscosity = 0.1;           // nu [-]
  bool steady = true;               // c = q = 1, else c(t) = q(t) = cos(t)

  // g and its x-derivatives, with w = 1 - x: g = 2 w^3 - w^4.
  static double g0(double x) { const double w = 1 - x; return 2 * w * w * w - w * w * w * w; }
  static double g1(double x) { const double w = 1 - x; return -6 * w * w + 4 * w * w * w; }
  static double g2(double x) { const double w = 1 - x; return 12 * w - 12 * w * w; }
  static double g3(double x) { const double w = 1 - x; return -12 + 24 * w; }
  // h and its y-derivatives.
  static double h0(double y) { const double s = std::sin(pi * y); return s * s; }
  static double h1(double y) { return pi * std::sin(2 * pi * y); }
  static double h2(double y) { return 2 * pi * pi * std::cos(2 * pi * y); }
  static double h3(double y) { return -4 * pi * pi * pi * std::sin(2 * pi * y); }
  static double a0(double x) { return (1 - x) * (2 + x); }
  static double a1(double x) { return -1 - 2 * x; }
  double c(double t) const { return steady ? 1.0 : std::cos(t); }
  double c_dot(double t) const { return steady ? 0.0 : -std::sin(t); }

  double u(double x, double y, double t) const { return amplitude * c(t) * g0(x) * h1(y); }
  double v(double x, double y, double t) const { return -amplitude * c(t) * g1(x) * h0(y); }
  double p(double x, double y, double t) const { return pressure_amplitude * c(t) * a0(x) * std::cos(pi * y); }

  double force_x(double x, double y, double t) const {
    const double A = amplitude * c(t);
    const double u_ = A * g0(x) * h1(y), v_ = -A * g1(x) * h0(y);
    const double u_t = amplitude * c_dot(t) * g0(x) * h1(y);
    const double u_x = A * g1(x) * h1(y), u_y = A * g0(x) * h2(y);
    const double lap = A * (g2(x) * h1(y) + g0(x) * h3(y));
    const double p_x = pressure_amplitude * c(t) * a1(x) * std::cos(pi * y);
    return u_t + u_ * u_x + v_ * u_y + p_x - viscosity * lap;
  }
  double force_y(double x, double y, double t) const {
    const double A = amplitude * c(t);
    const double u_ = A * g0(x) * h1(y), v_ = -A * g1(x) * h0(y);
    const double v_t = -amplitude * c_dot(t) * g1(x) * h0(y);
    const double v_x = -A * g2(x) * h0(y), v_y = -A * g1(x) * h1(y);
    const double lap = -A * (g3(x) * h0(y) + g1(x) * h2(y));
    const double p_y = -pressure_amplitude * c(t) * a0(x) * pi * std::sin(pi * y);
    return v_t + u_ * v_x + v_ * v_y + p_y - viscosity * lap;
  }
};

}  // namespace ibms::verification
