// The inner loop of the contacts (contact_subcycle.hpp, steps 2 and 3): the contact forces of the
// listed pairs and walls near contact, the candidates' kick and drift, and the points off the list
// moved in closed form, with the bounds on their speed and slow acceleration that keep the list valid.
#include "contact/contact_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/normal_contact_law.hpp"

namespace ibms {

namespace {

constexpr double near_margin = 1e-9;  // relative to r_a + r_b: round-off in the gap and the reach

// The candidates' kick and drift (ContactSubcycler::kick_and_drift) on arrays that do not overlap,
// without a running sum, so that the compiler puts it on vector registers; moved: the squared
// displacement since the list was built. Compiled also for AVX2 (chosen at run time where the CPU
// has it): twice the vector width, the same operations in the same order (no FMA), so the same
// bits.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && defined(__linux__) && defined(__GLIBC__)
__attribute__((target_clones("avx2", "default")))
#endif
void kick_and_drift_candidates(int n, double dt, double drift_time, double kick_time, double* __restrict x,
                               double* __restrict y, double* __restrict u, double* __restrict v,
                               double* __restrict moved, const double* __restrict force_x,
                               const double* __restrict force_y, const double* __restrict inverse_mass,
                               const double* __restrict slow_x, const double* __restrict slow_y,
                               const double* __restrict rate_x, const double* __restrict rate_y,
                               const double* __restrict anchor_x, const double* __restrict anchor_y) {
  for (int i = 0; i < n; ++i) {
    const double f_x = force_x[i] * inverse_mass[i], f_y = force_y[i] * inverse_mass[i];
    x[i] += dt * u[i] + dt * dt * (0.5 * slow_x[i] + rate_x[i] * drift_time + f_x);
    y[i] += dt * v[i] + dt * dt * (0.5 * slow_y[i] + rate_y[i] * drift_time + f_y);
    u[i] += dt * (slow_x[i] + rate_x[i] * kick_time + f_x);
    v[i] += dt * (slow_y[i] + rate_y[i] * kick_time + f_y);
    const double dx = x[i] - anchor_x[i], dy = y[i] - anchor_y[i];
    moved[i] = dx*dx + dy*dy;
  }
}


}  // namespace

void ContactSubcycler::activate(const Active& a) {
  active_.push_back(a);
  ParallelPairs& s = shares_[a.share];
  if (s.n_pairs == 0) touched_.push_back(a.share);
  s.add(a.normal);
}

// DEM forces on the candidates at their current state (contact_forces.cpp, restricted to the list),
// added to their force arrays (zero on entry: kick_and_drift clears them). The shares' sums are
// zero on entry too: only the shares with an active pair are visited and cleared again.
void ContactSubcycler::contact_forces(const ContactModel& model, double time, double moved, ContactStats& stats) {
  const double since_built = time - time_built_;
  // A pair of the list can touch only once its gap at the list's build has closed: by the two
  // points' displacements since (each at most `moved`) and the growth of the radii. The pairs whose
  // gap exceeds twice the needed reach are left out until the reach passes that bound.
  const double reach = 2.0 * moved + radius_rate_max_ * since_built;
  if (!(reach < near_reach_)) {
    near_reach_ = std::max(2.0 * reach, near_reach_floor_);
    near_.clear();
    for (int i = 0; i < static_cast<int>(pairs_.size()); ++i)
      if (!(gap_[i] > near_reach_ + near_margin * pairs_[i].radius_sum)) near_.push_back(i);
    pair_checks_ += static_cast<long>(pairs_.size());
  }
  const double* const x = points_.x.data();
  const double* const y = points_.y.data();
  active_.clear();
  for (const int i : near_) {
    const Pair& pair = pairs_[i];
    const double dx = x[pair.b] - x[pair.a] + pair.shift[0], dy = y[pair.b] - y[pair.a] + pair.shift[1];
    const double distance_squared = dx*dx + dy*dy;
    const double radius_sum = pair.radius_sum + since_built * pair.radius_rate;
    if (!(distance_squared < radius_sum * radius_sum)) continue;
    const double distance = std::sqrt(distance_squared);
    if (!(distance > 0.0)) throw std::runtime_error("contact: two CDS centres coincide");
    Active a;
    a.a = pair.a;
    a.b = pair.b;
    a.share = pair.share;
    a.stiffness = pair.stiffness;
    a.damping = pair.damping;
    a.overlap = radius_sum - distance;
    a.normal = {dx / distance, dy / distance};
    activate(a);
  }
  const int n_pairs = static_cast<int>(active_.size());
  for (const Wall& wall : walls_) {
    const double position = wall.axis == 0 ? x[wall.a] : y[wall.a];
    const double distance = wall.side == 0 ? position - wall.coordinate : wall.coordinate - position;
    const double overlap = wall.radius + since_built * wall.radius_rate - distance;
    if (!(overlap > 0.0)) continue;
    Active a;
    a.a = wall.a;
    a.share = wall.share;
    a.stiffness = wall.stiffness;
    a.damping = wall.damping;
    a.overlap = overlap;
    a.normal[wall.axis] = wall.side == 0 ? -1.0 : 1.0;
    activate(a);
  }
  stats.n_active_pairs = std::max(stats.n_active_pairs, n_pairs);
  stats.n_wall_contacts = std::max(stats.n_wall_contacts, static_cast<int>(active_.size()) - n_pairs);
  pair_checks_ += static_cast<long>(near_.size());
  if (active_.empty()) return;
  // S of each share, and its pairs' dashpot factor (normal_contact_law.hpp).
  if (model.share_damping_among_active_pairs) {
    for (const int k : touched_) shares_[k].close();
    for (const Active& a : active_) shares_[a.share].add_share(a.normal);
    for (const int k : touched_) share_factor_[k] = shares_[k].damping_factor();
  }
  double* const force_x = points_.force_x.data();
  double* const force_y = points_.force_y.data();
  const double* const u = points_.u.data();
  const double* const v = points_.v.data();
  for (const Active& a : active_) {
    stats.max_overlap = std::max(stats.max_overlap, a.overlap);
    // The law of normal_contact_law.hpp, v_n = (U_b - U_a) . n; walls are at rest.
    double relative_u = -u[a.a], relative_v = -v[a.a];
    if (a.b >= 0) {
      relative_u += u[a.b];
      relative_v += v[a.b];
    }
    double damping = a.damping;
    if (model.share_damping_among_active_pairs) damping *= share_factor_[a.share];
    const Vec force = contact_force_on_first({a.stiffness, damping}, {a.overlap, a.normal, {relative_u, relative_v}});
    force_x[a.a] += force[0];
    force_y[a.a] += force[1];
    forced_.push_back(a.a);
    if (a.b >= 0) {
      force_x[a.b] -= force[0];
      force_y[a.b] -= force[1];
      forced_.push_back(a.b);
    }
  }
  // The shares' sums back to zero for the next inner step.
  for (const int k : touched_) shares_[k] = ParallelPairs{};
  touched_.clear();
  // The points with a force, each once, in candidate order (the work sums in that order).
  std::sort(forced_.begin(), forced_.end());
  forced_.erase(std::unique(forced_.begin(), forced_.end()), forced_.end());
}

double ContactSubcycler::kick_and_drift(double dt, double time, double& work) {
  // Symplectic Euler for the contact force, the slow force a + r t integrated exactly.
  const double drift_time = 0.5 * time + dt / 6.0, kick_time = time + 0.5 * dt;
  const int n = points_.size();
  Candidates& p = points_;
  kick_and_drift_candidates(n, dt, drift_time, kick_time, p.x.data(), p.y.data(), p.u.data(), p.v.data(), moved_.data(),
                            p.force_x.data(), p.force_y.data(), p.inverse_mass.data(), p.slow_x.data(), p.slow_y.data(),
                            p.rate_x.data(), p.rate_y.data(), p.anchor_x.data(), p.anchor_y.data());
  const double* const u = p.u.data();
  const double* const v = p.v.data();
  const double* const moved = moved_.data();
  // Work of the contact forces in candidate order, over the points that have one (the others add
  // an exact zero); their forces cleared for the next inner step.
  double sum = work;
  for (const int i : forced_) {
    sum += dt * (points_.force_x[i]*u[i] + points_.force_y[i]*v[i]);
    points_.force_x[i] = points_.force_y[i] = 0.0;
  }
  work = sum;
  forced_.clear();
  // Largest displacement since the list was built: four running maxima (max is exact, any order).
  double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    m0 = std::max(m0, moved[i]);
    m1 = std::max(m1, moved[i + 1]);
    m2 = std::max(m2, moved[i + 2]);
    m3 = std::max(m3, moved[i + 3]);
  }
  for (; i < n; ++i) m0 = std::max(m0, moved[i]);
  return std::max(std::max(m0, m1), std::max(m2, m3));
}

void ContactSubcycler::move_off_list(const BodySet& members, std::vector<MassSpringBody>& bodies, double start,
                                     double span) {
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    MassSpringBody& body = bodies[b];
    for (int p = 0; p < body.n_points(); ++p) {
      if (slot_[offset_[b] + p] >= 0) continue;
      for (int c = 0; c < 2; ++c) {
        const double a = slow_[b][p][c] / body.mass[p], r = rate_[b][p][c] / body.mass[p];
        body.position[p][c] += span * body.velocity[p][c] + span * span * (0.5 * a + r * (0.5 * start + span / 6.0));
        body.velocity[p][c] += span * (a + r * (start + 0.5 * span));
      }
    }
  }
}

std::array<double, 2> ContactSubcycler::fastest(const BodySet& members, const std::vector<MassSpringBody>& bodies,
                                                bool off_list_only) const {
  std::array<double, 2> largest{0.0, 0.0};  // squared speed, squared slow acceleration
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    const MassSpringBody& body = bodies[b];
    for (int p = 0; p < body.n_points(); ++p) {
      if (off_list_only && slot_[offset_[b] + p] >= 0) continue;
      const Vec& u = body.velocity[p];
      const Vec& f = slow_[b][p];
      const Vec& r = rate_[b][p];
      // |F + r t| <= |F| + |r| t: the slow force's largest value over the step.
      const double force = std::sqrt(f[0]*f[0] + f[1]*f[1]) + previous_dt_ * std::sqrt(r[0]*r[0] + r[1]*r[1]);
      largest[0] = std::max(largest[0], u[0]*u[0] + u[1]*u[1]);
      largest[1] = std::max(largest[1], force * force / (body.mass[p] * body.mass[p]));
    }
  }
  return {std::sqrt(largest[0]), std::sqrt(largest[1])};
}

}  // namespace ibms
