// The contact force law of docs/method.md §1.9: linear normal spring-dashpot, no tangential force,
//   F_i = -(k delta - c v_n) n,  v_n = (U_j - U_i).n,  F_j = -F_i,
// with n the unit normal from CDS i to its partner j (a wall point for wall contacts); the spring
// repels and the dashpot resists approach (v_n < 0). Not clipped to stay repulsive: clipping
// changes the realised restitution (A8 caveat, Schwager & Poeschel 2007).
// Both the shared sub-step (contact_forces.cpp) and the contacts' inner loop
// (contact_subcycle_inner_loop.cpp) take their forces and their dashpot sharing from this file.
#pragma once
#include <array>
#include <cmath>

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
inline std::array<double, 2> contact_force_on_first(const ContactLaw& law, const ContactKinematics& contact) {
  const std::array<double, 2>& n = contact.normal;
  const double normal_rate = contact.relative_velocity[0]*n[0] + contact.relative_velocity[1]*n[1];
  // F_i = -(k delta - c v_n) n: approach (v_n < 0) adds to the repulsion.
  const double push = law.stiffness*contact.overlap - law.damping*normal_rate;
  return {-push * n[0], -push * n[1]};
}

// Dashpot sharing (ContactModel::share_damping_among_active_pairs, docs/method.md §1.9): the active
// pairs between the same two bodies (or a body and a wall) act in parallel, S = sum_p (n_p . N)^2
// of them along their unit mean normal N. A group's S is the sum of parallel_share over its pairs,
// or its number of pairs when their normals cancel (a body squeezed from both sides: mean_normal_length 0).
// The length of a group's normal sum, or 0 when the normals cancel [-].
inline double mean_normal_length(const std::array<double, 2>& normal_sum, int n_pairs) {
  const double length = std::hypot(normal_sum[0], normal_sum[1]);
  return length > 1e-12 * n_pairs ? length : 0.0;
}
// One pair's part of S, (n . N)^2, for a group with a non-zero mean_normal_length [-].
inline double parallel_share(const std::array<double, 2>& normal, const std::array<double, 2>& normal_sum,
                             double length) {
  const double projection = (normal[0]*normal_sum[0] + normal[1]*normal_sum[1]) / length;
  return projection * projection;
}

}  // namespace ibms
