// Symplectic Euler sub-step, docs/method.md §5.1 (stable for omega dt <= 2(sqrt(1+zeta^2) - zeta)).
#include "solid/symplectic_euler.hpp"

#include <stdexcept>

#include "solid/spring_forces.hpp"

namespace ibms {

void advance_symplectic_euler(MassSpringBody& body, double dt_sub,
                              const std::vector<std::array<double, 2>>& external_force_per_point) {
  std::vector<std::array<double, 2>> force = external_force_per_point;
  advance_symplectic_euler_in_place(body, dt_sub, force);
}

void advance_symplectic_euler_in_place(MassSpringBody& body, double dt_sub, std::vector<std::array<double, 2>>& force) {
  if (static_cast<int>(force.size()) != body.n_points())
    throw std::invalid_argument("advance_symplectic_euler: external force has the wrong size");
  add_spring_forces(body, body.length_scale(), force);
  for (int p = 0; p < body.n_points(); ++p) {
    // Velocity first, then position with the new velocity (the symplectic ordering).
    for (int c = 0; c < 2; ++c) {
      body.velocity[p][c] += dt_sub * force[p][c] / body.mass[p];
      body.position[p][c] += dt_sub * body.velocity[p][c];
    }
  }
}

}  // namespace ibms
