// Largest stable symplectic-Euler sub-step of a mass-spring body, docs/method.md §5.1 and §5.3:
// for a mode omega with damping rate gamma = 2 zeta omega, symplectic Euler is stable for
//   dt <= 2 (sqrt(1 + zeta^2) - zeta) / omega = 4 / (gamma + sqrt(gamma^2 + 4 omega^2)),
// with omega_max^2 bounded by a (diagonally scaled) Gershgorin bound of M^-1 K and gamma_max by
// the same bound of M^-1 C at the current configuration. Returns safety times that step [time].
#pragma once

#include <array>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

// Upper bounds on the spectral radii of M^-1 K (omega_max^2 [1/time^2]) and of M^-1 C
// (gamma_max [1/time]) at the current positions and swelling factor.
struct SpectralBounds {
  double omega_squared_max = 0.0;
  double damping_rate_max = 0.0;
};
// Scratch arrays of the bounds, kept by a caller that evaluates them every step so that no
// allocation happens once they have reached the body's size.
struct SpectralWorkspace {
  std::vector<std::array<double, 4>> stiffness_diag, damping_diag, stiffness_element, damping_element;
  std::vector<double> x, y;
};
SpectralBounds spectral_bounds(const MassSpringBody& body, SpectralWorkspace& work);
SpectralBounds spectral_bounds(const MassSpringBody& body);  // with its own scratch

// Infinity for a body without springs (rigid and prescribed kinds).
double stable_substep(const MassSpringBody& body, double safety, SpectralWorkspace& work);
double stable_substep(const MassSpringBody& body, double safety = 0.5);

}  // namespace ibms
