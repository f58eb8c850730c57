// The contact force law of docs/method.md §1.9: linear normal spring-dashpot, no tangential force,
//   F_i = -(k delta - c v_n) n,  v_n = (U_j - U_i).n,  F_j = -F_i,
// with n the unit normal from CDS i to its partner j (a wall point for wall contacts); the spring
// repels and the dashpot resists approach (v_n < 0). Not clipped to stay repulsive: clipping
// changes the realised restitution (A8 caveat, Schwager & Poeschel 2007).
#pragma once
#include <array>

namespace ibms {

// One active contact seen from CDS i.
struct ContactKinematics {
  double overlap = 0.0;                           // delta > 0 [length]
  std::array<double, 2> normal{0.0, 0.0};         // n, unit, from i towards its partner [-]
  std::array<double, 2> relative_velocity{0.0, 0.0};  // U_j - U_i [length/time]
};

// Coefficients of the law for one contact.
struct ContactLaw {
  double stiffness = 0.0;  // k [force/length^2 per unit depth]
  double damping = 0.0;    // c [force time/length^2 per unit depth]
};

// Force on CDS i [force/length]; its partner gets the opposite. This is the seam for a tangential
// model (e.g. Cundall-Strack spring with a Coulomb limit): it would add a term here from the
// tangential part of relative_velocity, with a per-contact history kept by the caller.
std::array<double, 2> contact_force_on_first(const ContactLaw& law, const ContactKinematics& contact);

}  // namespace ibms
