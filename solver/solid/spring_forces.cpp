// Spring-dashpot forces and elastic energy, docs/method.md §1.2.
#include "solid/spring_forces.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"

namespace ibms {

void add_spring_forces(const MassSpringBody& body, double length_scale,
                       std::vector<std::array<double, 2>>& force) {
  if (static_cast<int>(force.size()) != body.n_points())
    throw std::invalid_argument("add_spring_forces: force has the wrong size");
  for (const Spring& spring : body.springs) {
    const auto& xi = body.position[spring.i];
    const auto& xj = body.position[spring.j];
    const double dx = xj[0] - xi[0], dy = xj[1] - xi[1];
    const double length = std::sqrt(dx*dx + dy*dy);  // not std::hypot: this loop runs every sub-step (cavity run: -17 % time)
    if (!(length > 0.0))
      throw BlowUpError("spring between points " + std::to_string(spring.i) + " and " +
                        std::to_string(spring.j) + " has zero or non-finite length");
    const double ex = dx / length, ey = dy / length;
    const auto& ui = body.velocity[spring.i];
    const auto& uj = body.velocity[spring.j];
    // docs/method.md §1.2: tension k (L - s L0) plus dashpot c (U_j - U_i).e, along e.
    const double separation_rate = (uj[0] - ui[0])*ex + (uj[1] - ui[1])*ey;
    const double tension = spring.stiffness * (length - length_scale*spring.natural_length0) +
                           spring.damping * separation_rate;
    force[spring.i][0] += tension * ex;
    force[spring.i][1] += tension * ey;
    force[spring.j][0] -= tension * ex;
    force[spring.j][1] -= tension * ey;
  }
}

double spring_energy(const MassSpringBody& body, double length_scale) {
  double energy = 0.0;
  for (const Spring& spring : body.springs) {
    const auto& xi = body.position[spring.i];
    const auto& xj = body.position[spring.j];
    const double stretch = std::hypot(xj[0] - xi[0], xj[1] - xi[1]) -
                           length_scale*spring.natural_length0;
    energy += 0.5 * spring.stiffness * stretch*stretch;
  }
  return energy;
}

}  // namespace ibms
