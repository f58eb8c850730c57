// The contact force law of docs/method.md §1.9: linear normal spring-dashpot, no tangential force,
//   F_i = -(k delta - c v_n) n,  v_n = (U_j - U_i).n,  F_j = -F_i,
// with n the unit normal from CDS i to its partner j (a wall point for wall contacts); the spring
// repels and the dashpot resists approach (v_n < 0). Not clipped to stay repulsive: clipping
// changes the realised restitution (A8 caveat, Schwager & Poeschel 2007).
// Both the shared sub-step (contact_forces.cpp) and the contacts' inner loop
// (contact_subcycle_inner_loop.cpp) take their forces and their dashpot sharing from this file.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/contact_model.hpp"

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
// of them along their unit mean normal N, so that the group is one spring S k with dashpot S c for a
// rigid approach along N; each pair's dashpot is its own c divided by sqrt(S), which keeps the
// damping ratio of e_D for the group. S is the group's number of pairs when their normals cancel (a
// body squeezed from both sides: no common direction).
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

// S of one group, summed in two passes over its active pairs: every pair's normal (add), then,
// after close, every pair's (n . N)^2 (add_share). Both contact paths (the shared sub-step and the
// inner loop) share their dashpots through it.
struct ParallelPairs {
  std::array<double, 2> normal_sum{0.0, 0.0};
  int n_pairs = 0;
  double length = 0.0;  // mean_normal_length of the group
  double s = 0.0;       // S

  void add(const std::array<double, 2>& normal) {
    normal_sum[0] += normal[0];
    normal_sum[1] += normal[1];
    ++n_pairs;
  }
  void close() {
    length = mean_normal_length(normal_sum, n_pairs);
    if (length == 0.0) s = n_pairs;
  }
  void add_share(const std::array<double, 2>& normal) {
    if (length != 0.0) s += parallel_share(normal, normal_sum, length);
  }
  // The factor of each pair's own dashpot constant: 1 / sqrt(S) [-].
  double damping_factor() const { return 1.0 / std::sqrt(s); }
};

// The groups that share a dashpot, each keyed by its two bodies or by a body and a wall; groups in touch are few, so a key is found by a linear look-up in a
// vector whose capacity is reused (no allocation once grown).
class DashpotGroups {
 public:
  void clear() {
    groups_.clear();
    last_ = 0;
  }
  void reserve(std::size_t n) { groups_.reserve(n); }
  // The group of this key (contact_group_key, wall_group_key), added with empty sums if it is new.
  // Consecutive look-ups often ask for the same group (the pair search lists a body pair's pairs
  // together), so the last group found is tried first.
  int index(const std::array<int, 2>& key) {
    const auto is = [&key](const Group& g) { return g.key[0] == key[0] && g.key[1] == key[1]; };
    if (last_ < groups_.size() && is(groups_[last_])) return static_cast<int>(last_);
    for (last_ = 0; last_ < groups_.size(); ++last_)
      if (is(groups_[last_])) return static_cast<int>(last_);
    groups_.push_back({key, {}});
    return static_cast<int>(last_);
  }
  ParallelPairs& operator[](int g) { return groups_[g].sums; }
  const ParallelPairs& operator[](int g) const { return groups_[g].sums; }
  int size() const { return static_cast<int>(groups_.size()); }

 private:
  struct Group {
    std::array<int, 2> key{};
    ParallelPairs sums;
  };
  std::vector<Group> groups_;
  std::size_t last_ = 0;  // the group of the last look-up
};

// The key of a contact's dashpot group: {min, max} of two bodies; a body and wall w (0..3) give
// {body, -1 - w}.
inline std::array<int, 2> contact_group_key(int body_a, int body_b) {
  return {std::min(body_a, body_b), std::max(body_a, body_b)};
}
inline std::array<int, 2> wall_group_key(int body, int wall) { return {body, -1 - wall}; }

// Walls of a box within reach: visit(point, axis, side, distance) for every surface point k <
// n_surface whose CDS centre lies closer than radius + reach to a wall of the box (non-periodic
// directions, walls of WallBox::is_wall), in the order point, axis, side; distance from the centre
// to that wall [length]. Wall w = 2 axis + side (x = x0, x = x0 + Lx, y = y0, y = y0 + Ly).
template <class Visit>
void for_each_point_near_walls(const std::vector<std::array<double, 2>>& position, int n_surface, const WallBox& box,
                               double radius, double reach, Visit&& visit) {
  for (int k = 0; k < n_surface; ++k)
    for (int c = 0; c < 2; ++c) {
      if (box.periodic[c]) continue;
      const double x = position[k][c];
      const double distance[2] = {x - box.origin[c], box.origin[c] + box.length[c] - x};
      for (int side = 0; side < 2; ++side) {
        if (!box.is_wall(c, side)) continue;
        if (!(distance[side] - radius < reach)) continue;
        visit(k, c, side, distance[side]);
      }
    }
}

}  // namespace ibms
