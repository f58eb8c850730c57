// Spring-dashpot forces of a mass-spring body, docs/method.md §1.2: for element (i, j) with
// e = (x_j - x_i)/|x_j - x_i| and natural length s L0 (s = D/D0, swelling),
//   F_ij = [k (|x_j - x_i| - s L0) + c (U_j - U_i).e] e  on i,   F_ji = -F_ij.
// Forces per unit depth [force/length]; energies [energy/length].
#pragma once
#include <array>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

// Adds the spring-dashpot forces to force (size n_points, not cleared).
void add_spring_forces(const MassSpringBody& body, double length_scale,
                       std::vector<std::array<double, 2>>& force);

// Elastic energy sum k (|x_j - x_i| - s L0)^2 / 2.
double spring_energy(const MassSpringBody& body, double length_scale);

}  // namespace ibms
