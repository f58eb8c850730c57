// One symplectic (semi-implicit) Euler sub-step of a mass-spring body, docs/method.md §5.1, §5.3:
//   U^{k+1} = U^k + dt (F_s(x^k, U^k) + F_ext) / M,   x^{k+1} = x^k + dt U^{k+1},
// springs and dashpots re-evaluated at x^k, U^k with natural lengths s L0 (s = D/D0); the
// external force per point (fluid reaction, internal-fluid term, contacts, buoyant gravity
// [force/length]) is frozen over the fluid step by the caller.
#pragma once
#include <array>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

void advance_symplectic_euler(MassSpringBody& body, double dt_sub,
                              const std::vector<std::array<double, 2>>& external_force_per_point);

// The same step without allocating: `force` holds the external force per point on entry and the
// total force (springs added) on return.
void advance_symplectic_euler_in_place(MassSpringBody& body, double dt_sub, std::vector<std::array<double, 2>>& force);

}  // namespace ibms
