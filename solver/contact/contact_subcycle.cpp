// Inner loop of the DEM contacts over the points near a contact (contact_subcycle.hpp).
#include "contact/contact_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/normal_contact_law.hpp"
#include "core/collatz_wielandt.hpp"
#include "core/constants.hpp"
#include "solid/spring_dashpot.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {

namespace {

constexpr double skin_travel_factor = 1.5;   // s = 2 * 1.5 * V * (time left): candidates may speed up
constexpr double skin_floor_fraction = 0.1;  // s >= 0.1 r_cds: bodies at rest do not rebuild every step
constexpr double near_margin = 1e-9;         // relative to r_a + r_b: round-off in the gap and the reach

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

void ContactSubcycler::Candidates::clear() {
  for (std::vector<int>* a : {&body, &point}) a->clear();
  for (std::vector<double>* a : {&inverse_mass, &x, &y, &u, &v, &force_x, &force_y, &anchor_x, &anchor_y, &slow_x,
                                 &slow_y, &rate_x, &rate_y})
    a->clear();
}

void ContactSubcycler::Candidates::reserve(std::size_t n) {
  for (std::vector<int>* a : {&body, &point}) a->reserve(n);
  for (std::vector<double>* a : {&inverse_mass, &x, &y, &u, &v, &force_x, &force_y, &anchor_x, &anchor_y, &slow_x,
                                 &slow_y, &rate_x, &rate_y})
    a->reserve(n);
}

int ContactSubcycler::candidate(int body, int point, const std::vector<MassSpringBody>& bodies) {
  int& slot = slot_[offset_[body] + point];
  if (slot >= 0) return slot;
  slot = points_.size();
  Candidates& p = points_;
  const double inverse_mass = 1.0 / bodies[body].mass[point];
  const Vec& x = bodies[body].position[point];
  const Vec& u = bodies[body].velocity[point];
  p.body.push_back(body);
  p.point.push_back(point);
  p.inverse_mass.push_back(inverse_mass);
  p.x.push_back(x[0]);
  p.y.push_back(x[1]);
  p.anchor_x.push_back(x[0]);
  p.anchor_y.push_back(x[1]);
  p.u.push_back(u[0]);
  p.v.push_back(u[1]);
  p.force_x.push_back(0.0);
  p.force_y.push_back(0.0);
  p.slow_x.push_back(slow_[body][point][0] * inverse_mass);
  p.slow_y.push_back(slow_[body][point][1] * inverse_mass);
  p.rate_x.push_back(rate_[body][point][0] * inverse_mass);
  p.rate_y.push_back(rate_[body][point][1] * inverse_mass);
  return slot;
}

int ContactSubcycler::share_of(int body_a, int partner) {
  for (std::size_t s = 0; s < shares_.size(); ++s)
    if (shares_[s].body_a == body_a && shares_[s].partner == partner) return static_cast<int>(s);
  Share share;
  share.body_a = body_a;
  share.partner = partner;
  shares_.push_back(share);
  return static_cast<int>(shares_.size()) - 1;
}

void ContactSubcycler::release_list(std::vector<MassSpringBody>& bodies) {
  for (int i = 0; i < points_.size(); ++i) {
    const int body = points_.body[i], point = points_.point[i];
    bodies[body].position[point] = {points_.x[i], points_.y[i]};
    bodies[body].velocity[point] = {points_.u[i], points_.v[i]};
    slot_[offset_[body] + point] = -1;
  }
  points_.clear();
  pairs_.clear();
  gap_.clear();
  near_.clear();
  walls_.clear();
  shares_.clear();
  forced_.clear();
  touched_.clear();
}

void ContactSubcycler::build_list(const ContactModel& model, const WallBox& box, double skin,
                                  const BodySet& members, const std::vector<MassSpringBody>& bodies, double time) {
  time_built_ = time;
  gap_.clear();
  near_.clear();
  near_reach_ = -1.0;  // the pairs near contact are picked at the first inner step
  near_reach_floor_ = skin / 16.0;
  radius_rate_max_ = 0.0;
  const double half_skin = 0.5 * skin;
  const double zeta_factor = 2.0 * damping_ratio_from_restitution(model.restitution_coefficient);
  // Pairs of different bodies closer than the skin: the pair search on CDS grown by s / 2.
  gather_contact_spheres(model, bodies, spheres_, members);
  for (int s = 0; s < spheres_.n_spheres(); ++s) spheres_.radius[s] += time * radius_rate_[spheres_.body[s]];
  const bool several_bodies = std::any_of(spheres_.body.begin(), spheres_.body.end(),
                                          [&](int b) { return b != spheres_.body.front(); });
  if (several_bodies) {
    for (double& r : spheres_.radius) r += half_skin;
    find_touching_pairs_body_bounds(spheres_, box, search_);
    pair_checks_ += search_.n_pair_checks;
    for (const SpherePair& found : search_.pairs) {
      const int s = found.first, t = found.second;
      const int body_s = spheres_.body[s], body_t = spheres_.body[t];
      Pair pair;
      pair.a = candidate(body_s, spheres_.point[s], bodies);
      pair.b = candidate(body_t, spheres_.point[t], bodies);
      const Vec xa{points_.x[pair.a], points_.y[pair.a]};
      const Vec xb{points_.x[pair.b], points_.y[pair.b]};
      const Vec d = separation(xa, xb, box);
      pair.shift = {d[0] - (xb[0] - xa[0]), d[1] - (xb[1] - xa[1])};
      pair.radius_sum = spheres_.radius[s] + spheres_.radius[t] - skin;
      pair.radius_rate = radius_rate_[body_s] + radius_rate_[body_t];
      const double m_eff = contact_effective_mass(model, bodies, body_s, spheres_.point[s], body_t, spheres_.point[t]);
      pair.stiffness = model.pair_stiffness(m_eff);
      pair.damping = zeta_factor * std::sqrt(m_eff * pair.stiffness);
      pair.share = share_of(std::min(body_s, body_t), std::max(body_s, body_t));
      pairs_.push_back(pair);
      gap_.push_back(std::sqrt(d[0]*d[0] + d[1]*d[1]) - pair.radius_sum);
      radius_rate_max_ = std::max(radius_rate_max_, std::abs(pair.radius_rate));
    }
  }
  // Walls: CDS closer to a wall than s / 2.
  if (model.walls) {
    for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
      const int b = static_cast<int>(members.at(i));
      const double radius = model.cds_radius_of(bodies[b]) + time * radius_rate_[b];
      for (int k = 0; k < bodies[b].n_surface; ++k) {
        for (int c = 0; c < 2; ++c) {
          if (box.periodic[c]) continue;
          const double x = bodies[b].position[k][c];
          const double wall_coordinate[2] = {box.origin[c], box.origin[c] + box.length[c]};
          for (int side = 0; side < 2; ++side) {
            if (!box.is_wall(c, side)) continue;
            const double distance = side == 0 ? x - wall_coordinate[0] : wall_coordinate[1] - x;
            if (!(distance - radius < half_skin)) continue;
            Wall wall;
            wall.a = candidate(b, k, bodies);
            wall.axis = c;
            wall.side = side;
            wall.radius = radius;
            wall.radius_rate = radius_rate_[b];
            wall.coordinate = wall_coordinate[side];
            const double m_eff = contact_effective_mass(model, bodies, b, k, -1, 0);
            wall.stiffness = model.pair_stiffness(m_eff);
            wall.damping = zeta_factor * std::sqrt(m_eff * wall.stiffness);
            wall.share = share_of(b, -1 - (2*c + side));
            walls_.push_back(wall);
          }
        }
      }
    }
  }
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
    active_.push_back(a);
    Share& s = shares_[pair.share];
    if (s.n_active == 0) touched_.push_back(pair.share);
    s.normal_sum[0] += a.normal[0];
    s.normal_sum[1] += a.normal[1];
    ++s.n_active;
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
    active_.push_back(a);
    Share& s = shares_[wall.share];
    if (s.n_active == 0) touched_.push_back(wall.share);
    s.normal_sum[0] += a.normal[0];
    s.normal_sum[1] += a.normal[1];
    ++s.n_active;
  }
  stats.n_active_pairs = std::max(stats.n_active_pairs, n_pairs);
  stats.n_wall_contacts = std::max(stats.n_wall_contacts, static_cast<int>(active_.size()) - n_pairs);
  pair_checks_ += static_cast<long>(near_.size());
  if (active_.empty()) return;
  // S of each share (normal_contact_law.hpp: mean_normal_length, parallel_share).
  if (model.share_damping_among_active_pairs) {
    for (const int k : touched_) {
      Share& s = shares_[k];
      s.length = mean_normal_length(s.normal_sum, s.n_active);
      if (s.length == 0.0) s.parallel = static_cast<double>(s.n_active);
    }
    for (const Active& a : active_) {
      Share& s = shares_[a.share];
      if (s.length != 0.0) s.parallel += parallel_share(a.normal, s.normal_sum, s.length);
    }
    for (const int k : touched_) shares_[k].inverse_sqrt_s = 1.0 / std::sqrt(shares_[k].parallel);
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
    if (model.share_damping_among_active_pairs) damping *= shares_[a.share].inverse_sqrt_s;
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
  for (const int k : touched_) {
    Share& s = shares_[k];
    s.normal_sum = {0.0, 0.0};
    s.n_active = 0;
    s.parallel = 0.0;
  }
  touched_.clear();
  // The points with a force, each once, in candidate order (the work sums in that order).
  std::sort(forced_.begin(), forced_.end());
  forced_.erase(std::unique(forced_.begin(), forced_.end()), forced_.end());
}

double ContactSubcycler::listed_pairs_step(const ContactModel& model) {
  // The contact modes of the listed pairs solve M x'' + C x' + K x = 0. Their rates |lambda| are
  // at most sqrt(omega_K^2) + omega_C with omega_K^2 and omega_C the largest eigenvalues of
  // M^-1/2 K M^-1/2 and M^-1/2 C M^-1/2 (one oscillator: |lambda| <= c / m + sqrt(k / m)). Each is
  // at most the spectral radius of its matrix of 2x2 block norms (||A|| <= ||B|| for a symmetric A
  // and its block-norm matrix B): diagonal sum over the candidate's pairs and walls of k / m_i (a
  // pair's k n n^T has norm k), off-diagonal k / sqrt(m_i m_j), and the same with the pairs'
  // dashpots c (unshared: an upper bound while S >= 1, i.e. unless two pairs of one body pair have
  // normals more than 90 degrees apart, which convex rims do not form; the dashpot bound of
  // contact_substep assumes the same); collatz_wielandt_bound bounds that radius from above.
  // One undamped pair of masses m_a, m_b gives k / m_eff exactly: A8's t_c.
  if (points_.empty()) return HUGE_VAL;
  stiffness_sum_.assign(points_.size(), 0.0);
  damping_sum_.assign(points_.size(), 0.0);
  const double* const inverse_mass = points_.inverse_mass.data();
  bool damped = false;
  for (const Pair& pair : pairs_) {
    stiffness_sum_[pair.a] += pair.stiffness * inverse_mass[pair.a];
    stiffness_sum_[pair.b] += pair.stiffness * inverse_mass[pair.b];
    damping_sum_[pair.a] += pair.damping * inverse_mass[pair.a];
    damping_sum_[pair.b] += pair.damping * inverse_mass[pair.b];
    damped = damped || pair.damping > 0.0;
  }
  for (const Wall& wall : walls_) {
    stiffness_sum_[wall.a] += wall.stiffness * inverse_mass[wall.a];
    damping_sum_[wall.a] += wall.damping * inverse_mass[wall.a];
    damped = damped || wall.damping > 0.0;
  }
  // The block-norm matrix with the given diagonal and, for each listed pair p = (a, b), the entry
  // w_p / sqrt(m_a m_b), w_p the pair's stiffness (damping: its dashpot); x stays > 0 (every
  // diagonal is > 0), so no floor.
  constexpr int iterations = 8;
  const auto radius = [&](const std::vector<double>& diagonal, bool damping) {
    return collatz_wielandt_bound(points_.size(), iterations, /*floor=*/0.0, perron_x_, perron_y_,
                                  [&](const std::vector<double>& x, std::vector<double>& y) {
      for (std::size_t i = 0; i < x.size(); ++i) y[i] = diagonal[i] * x[i];
      for (const Pair& pair : pairs_) {
        const double w = (damping ? pair.damping : pair.stiffness) * std::sqrt(inverse_mass[pair.a] * inverse_mass[pair.b]);
        y[pair.a] += w * x[pair.b];
        y[pair.b] += w * x[pair.a];
      }
    });
  };
  const double omega_k = std::sqrt(radius(stiffness_sum_, false));
  const double omega_c = damped ? radius(damping_sum_, true) : 0.0;
  // t_c = pi / |lambda|, steps_per_contact steps in it.
  const double rate = omega_k + omega_c;
  return rate > 0.0 ? pi / (model.steps_per_contact * rate) : HUGE_VAL;
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

ContactSubcycleResult ContactSubcycler::advance(const ContactModel& model, const WallBox& box, double dt_outer,
                                                int n_inner,
                                                const std::vector<std::vector<std::array<double, 2>>>& external_force,
                                                const BodySet& members, std::vector<MassSpringBody>& bodies,
                                                bool continues, const std::vector<double>& diameter_rate) {
  if (n_inner < 1) throw std::invalid_argument("ContactSubcycler: n_inner must be >= 1");
  if (external_force.size() != bodies.size()) throw std::invalid_argument("ContactSubcycler: one force vector per body");
  ContactSubcycleResult result;
  pair_checks_ = 0;
  // Index of every point (made once for the scene's bodies; entries are -1 outside a list). A call
  // on a group checks only its members' counts, so that it costs O(members), not O(bodies).
  bool offsets_hold = offset_.size() == bodies.size() + 1;
  for (std::size_t i = 0; offsets_hold && i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    offsets_hold = offset_[b + 1] - offset_[b] == bodies[b].n_points();
  }
  if (!offsets_hold) {
    offset_.resize(bodies.size() + 1);
    offset_[0] = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) offset_[b + 1] = offset_[b] + bodies[b].n_points();
  }
  if (static_cast<int>(slot_.size()) != offset_.back()) {
    slot_.assign(offset_.back(), -1);
    // Room for every point of the scene and many pairs each: no growth inside later steps.
    points_.reserve(offset_.back());
    moved_.resize(offset_.back());
    stiffness_sum_.reserve(offset_.back());
    perron_x_.reserve(offset_.back());
    perron_y_.reserve(offset_.back());
    damping_sum_.reserve(offset_.back());
    forced_.reserve(2 * 10 * offset_.back());
    touched_.reserve(8 * bodies.size() + 8);
    pairs_.reserve(8 * offset_.back());
    gap_.reserve(8 * offset_.back());
    near_.reserve(8 * offset_.back());
    search_.pairs.reserve(8 * offset_.back());
    walls_.reserve(2 * offset_.back());
    active_.reserve(10 * offset_.back());
    shares_.reserve(8 * bodies.size() + 8);  // body pairs and body-wall pairs in touch
    spheres_.centre.reserve(offset_.back());
    spheres_.radius.reserve(offset_.back());
    spheres_.body.reserve(offset_.back());
    spheres_.point.reserve(offset_.back());
  }
  slow_.resize(bodies.size());
  spring_.resize(bodies.size());
  rate_.resize(bodies.size());
  previous_slow_.resize(bodies.size());
  radius_rate_.resize(bodies.size());  // the members' entries are set here and read below
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    radius_rate_[b] =
        !diameter_rate.empty() && model.cds_radius == 0.0 ? model.cds_radius_fraction * diameter_rate[b] : 0.0;
  }
  double smallest_radius = HUGE_VAL;
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    const MassSpringBody& body = bodies[b];
    if (body.kind != BodyKind::mass_spring)
      throw std::invalid_argument("ContactSubcycler: only mass_spring bodies take the contact inner loop");
    if (external_force[b].size() != body.position.size())
      throw std::invalid_argument("ContactSubcycler: external force has the wrong size");
    smallest_radius = std::min(smallest_radius, model.cds_radius_of(body));
    // F_slow = external + springs and dashpots at x^k, U^k; the springs alone kept for step 4.
    spring_[b].assign(body.n_points(), Vec{0.0, 0.0});
    add_spring_forces(body, body.length_scale(), spring_[b]);
    slow_[b].resize(body.n_points());
    for (int p = 0; p < body.n_points(); ++p)
      for (int c = 0; c < 2; ++c) slow_[b][p][c] = external_force[b][p][c] + spring_[b][p][c];
    rate_[b].assign(body.n_points(), Vec{0.0, 0.0});
    if (continues && previous_slow_[b].size() == slow_[b].size() && previous_dt_ > 0.0)
      for (int p = 0; p < body.n_points(); ++p)
        for (int c = 0; c < 2; ++c) rate_[b][p][c] = (slow_[b][p][c] - previous_slow_[b][p][c]) / previous_dt_;
    previous_slow_[b].assign(slow_[b].begin(), slow_[b].end());
  }
  previous_dt_ = dt_outer;
  const double skin_floor = skin_floor_fraction * smallest_radius;
  double growth = 0.0;  // fastest CDS radius growth [length/time]: two radii close a gap at twice it
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i)
    growth = std::max(growth, std::abs(radius_rate_[members.at(i)]));
  const bool listed_pairs = model.inner_step == InnerStepBound::listed_pairs;
  const double dashpot_limit = listed_pairs ? contact_dashpot_substep(model, bodies, members) : HUGE_VAL;
  // Skin for the time left: the travel bound V T + A T^2 / 2 of a point without contact.
  const auto travel = [](const std::array<double, 2>& largest, double time) {
    return largest[0] * time + 0.5 * largest[1] * time * time;
  };
  double skin = std::max(2.0 * skin_travel_factor * (travel(fastest(members, bodies, false), dt_outer) + growth * dt_outer),
                         skin_floor);
  build_list(model, box, skin, members, bodies, 0.0);
  result.list_builds = 1;
  // The inner steps run in segments of equal steps h from segment_start: one segment of n_inner
  // steps (lightest_point), or a new segment at every list, its step from the listed pairs.
  double segment_start = 0.0;
  int segment_steps = n_inner;
  const auto plan_segment = [&] {
    if (!listed_pairs) return;
    const double left = dt_outer - segment_start;
    const double limit = std::min(listed_pairs_step(model), dashpot_limit);
    if (!(limit > 0.0)) throw std::runtime_error("contact inner loop: the listed pairs give no positive inner step");
    if (!std::isfinite(limit)) {
      segment_steps = 1;
      return;
    }
    const double steps = std::ceil(left / limit * (1.0 - 1e-12));
    if (!(steps < 1e9)) throw std::runtime_error("contact inner loop: more than 1e9 inner steps in one outer step");
    segment_steps = std::max(1, static_cast<int>(steps));
  };
  plan_segment();
  double h = (dt_outer - segment_start) / segment_steps;
  std::array<double, 2> off_list = fastest(members, bodies, /*off_list_only=*/true);
  int step_built = 0;   // inner step of the segment at which the list was built
  int step_synced = 0;  // inner step of the segment the off-list points' stored state belongs to
  double moved_squared = 0.0;  // largest squared displacement of a candidate since the list was built
  for (int j = 0; j < segment_steps && !points_.empty(); ++j) {
    if (j > step_built) {
      // The list holds while no two points can have closed the skin since it was built.
      const double moved = std::max(std::sqrt(moved_squared), travel(off_list, (j - step_built) * h)) +
                           growth * (j - step_built) * h;
      if (2.0 * moved >= skin) {
        // Every point to this inner step, then a new list for the time left.
        move_off_list(members, bodies, segment_start + step_synced * h, (j - step_synced) * h);
        const double now = segment_start + j * h;
        release_list(bodies);
        skin = std::max(2.0 * skin_travel_factor *
                            (travel(fastest(members, bodies, false), dt_outer - now) + growth * (dt_outer - now)),
                        skin_floor);
        build_list(model, box, skin, members, bodies, now);
        moved_squared = 0.0;
        ++result.list_builds;
        off_list = fastest(members, bodies, true);
        step_synced = step_built = j;
        if (listed_pairs) {
          segment_start = now;
          plan_segment();
          h = (dt_outer - segment_start) / segment_steps;
          step_synced = step_built = j = 0;
        }
        if (points_.empty()) break;
      }
    }
    const double now = segment_start + j * h;
    contact_forces(model, now, std::sqrt(moved_squared), result.stats);
    moved_squared = kick_and_drift(h, now, result.work);
    ++result.inner_steps;
  }
  move_off_list(members, bodies, segment_start + step_synced * h, (segment_steps - step_synced) * h);
  release_list(bodies);
  // Step 4: U += dt (F_s(x^{k+1}, U*) - F_s(x^k, U^k) - dt r) / (2 m): the velocity change over
  // the step becomes dt (F^k + F^{k+1}) / (2 m), what the extrapolated rate r gave taken back.
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    MassSpringBody& body = bodies[b];
    for (Vec& f : spring_[b]) f = {-f[0], -f[1]};
    add_spring_forces(body, body.length_scale(), spring_[b]);
    for (int p = 0; p < body.n_points(); ++p)
      for (int c = 0; c < 2; ++c)
        body.velocity[p][c] += 0.5 * dt_outer * (spring_[b][p][c] - dt_outer * rate_[b][p][c]) / body.mass[p];
  }
  result.stats.n_pair_checks = pair_checks_;
  return result;
}

}  // namespace ibms
