// Inner loop of the DEM contacts over the points near a contact (contact_subcycle.hpp).
#include "contact/contact_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solid/spring_dashpot.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {

namespace {

constexpr double skin_travel_factor = 1.5;   // s = 2 * 1.5 * V * (time left): candidates may speed up
constexpr double skin_floor_fraction = 0.1;  // s >= 0.1 r_cds: bodies at rest do not rebuild every step

}  // namespace

int ContactSubcycler::candidate(int body, int point, const std::vector<MassSpringBody>& bodies) {
  int& slot = slot_[offset_[body] + point];
  if (slot >= 0) return slot;
  slot = static_cast<int>(points_.size());
  Point p;
  p.body = body;
  p.point = point;
  p.inverse_mass = 1.0 / bodies[body].mass[point];
  p.position = p.anchor = bodies[body].position[point];
  p.velocity = bodies[body].velocity[point];
  for (int c = 0; c < 2; ++c) {
    p.slow_acceleration[c] = slow_[body][point][c] * p.inverse_mass;
    p.slow_rate[c] = rate_[body][point][c] * p.inverse_mass;
  }
  points_.push_back(p);
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
  for (const Point& p : points_) {
    bodies[p.body].position[p.point] = p.position;
    bodies[p.body].velocity[p.point] = p.velocity;
    slot_[offset_[p.body] + p.point] = -1;
  }
  points_.clear();
  pairs_.clear();
  walls_.clear();
  shares_.clear();
}

void ContactSubcycler::build_list(const ContactModel& model, const WallBox& box, double skin,
                                  const BodyMask& members, const std::vector<MassSpringBody>& bodies, double time) {
  time_built_ = time;
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
      const Vec& xa = points_[pair.a].position;
      const Vec& xb = points_[pair.b].position;
      const Vec d = separation(xa, xb, box);
      pair.shift = {d[0] - (xb[0] - xa[0]), d[1] - (xb[1] - xa[1])};
      pair.radius_sum = spheres_.radius[s] + spheres_.radius[t] - skin;
      pair.radius_rate = radius_rate_[body_s] + radius_rate_[body_t];
      const double m_eff = contact_effective_mass(model, bodies, body_s, spheres_.point[s], body_t, spheres_.point[t]);
      pair.stiffness = model.pair_stiffness(m_eff);
      pair.damping = zeta_factor * std::sqrt(m_eff * pair.stiffness);
      pair.share = share_of(std::min(body_s, body_t), std::max(body_s, body_t));
      pairs_.push_back(pair);
    }
  }
  // Walls: CDS closer to a wall than s / 2.
  if (model.walls) {
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
      if (!selected(members, b)) continue;
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

// DEM forces on the candidates at their current state (contact_forces.cpp, restricted to the list).
void ContactSubcycler::contact_forces(const ContactModel& model, double time, ContactStats& stats) {
  const double since_built = time - time_built_;
  for (Point& p : points_) p.force = {0.0, 0.0};
  for (Share& s : shares_) {
    s.normal_sum = {0.0, 0.0};
    s.n_active = 0;
  }
  active_.clear();
  for (int i = 0; i < static_cast<int>(pairs_.size()); ++i) {
    const Pair& pair = pairs_[i];
    const Vec& xa = points_[pair.a].position;
    const Vec& xb = points_[pair.b].position;
    const double dx = xb[0] - xa[0] + pair.shift[0], dy = xb[1] - xa[1] + pair.shift[1];
    const double distance_squared = dx*dx + dy*dy;
    const double radius_sum = pair.radius_sum + since_built * pair.radius_rate;
    if (!(distance_squared < radius_sum * radius_sum)) continue;
    const double distance = std::sqrt(distance_squared);
    if (!(distance > 0.0)) throw std::runtime_error("contact: two CDS centres coincide");
    Active a;
    a.index = i;
    a.overlap = radius_sum - distance;
    a.normal = {dx / distance, dy / distance};
    active_.push_back(a);
    Share& s = shares_[pair.share];
    s.normal_sum[0] += a.normal[0];
    s.normal_sum[1] += a.normal[1];
    ++s.n_active;
  }
  int n_pairs = static_cast<int>(active_.size());
  for (int i = 0; i < static_cast<int>(walls_.size()); ++i) {
    const Wall& wall = walls_[i];
    const double x = points_[wall.a].position[wall.axis];
    const double distance = wall.side == 0 ? x - wall.coordinate : wall.coordinate - x;
    const double overlap = wall.radius + since_built * wall.radius_rate - distance;
    if (!(overlap > 0.0)) continue;
    Active a;
    a.index = i;
    a.wall = true;
    a.overlap = overlap;
    a.normal[wall.axis] = wall.side == 0 ? -1.0 : 1.0;
    active_.push_back(a);
    Share& s = shares_[wall.share];
    s.normal_sum[0] += a.normal[0];
    s.normal_sum[1] += a.normal[1];
    ++s.n_active;
  }
  stats.n_active_pairs = std::max(stats.n_active_pairs, n_pairs);
  stats.n_wall_contacts = std::max(stats.n_wall_contacts, static_cast<int>(active_.size()) - n_pairs);
  pair_checks_ += static_cast<long>(pairs_.size());
  if (active_.empty()) return;
  // S of each share, as count_parallel_pairs in contact_forces.cpp: sum of (n_p . N)^2 with N the
  // unit mean normal; normals that cancel count one each.
  if (model.share_damping_among_active_pairs) {
    projection_.assign(shares_.size(), 0.0);
    for (const Active& a : active_) {
      const Share& s = shares_[a.wall ? walls_[a.index].share : pairs_[a.index].share];
      const double length = std::hypot(s.normal_sum[0], s.normal_sum[1]);
      if (!(length > 1e-12 * s.n_active)) continue;
      const double projection = (a.normal[0]*s.normal_sum[0] + a.normal[1]*s.normal_sum[1]) / length;
      projection_[&s - shares_.data()] += projection * projection;
    }
    for (std::size_t k = 0; k < shares_.size(); ++k) {
      Share& s = shares_[k];
      if (s.n_active == 0) continue;
      const double length = std::hypot(s.normal_sum[0], s.normal_sum[1]);
      const double parallel = length > 1e-12 * s.n_active ? projection_[k] : static_cast<double>(s.n_active);
      s.inverse_sqrt_s = 1.0 / std::sqrt(parallel);
    }
  }
  for (const Active& a : active_) {
    stats.max_overlap = std::max(stats.max_overlap, a.overlap);
    // F_a = -(k delta - c v_n) n, v_n = (U_b - U_a) . n (normal_contact_law.hpp); walls are at rest.
    Point& pa = points_[a.wall ? walls_[a.index].a : pairs_[a.index].a];
    Vec relative{-pa.velocity[0], -pa.velocity[1]};
    Point* pb = nullptr;
    double stiffness = 0.0, damping = 0.0;
    int share = 0;
    if (a.wall) {
      stiffness = walls_[a.index].stiffness;
      damping = walls_[a.index].damping;
      share = walls_[a.index].share;
    } else {
      pb = &points_[pairs_[a.index].b];
      relative[0] += pb->velocity[0];
      relative[1] += pb->velocity[1];
      stiffness = pairs_[a.index].stiffness;
      damping = pairs_[a.index].damping;
      share = pairs_[a.index].share;
    }
    if (model.share_damping_among_active_pairs) damping *= shares_[share].inverse_sqrt_s;
    const double normal_rate = relative[0]*a.normal[0] + relative[1]*a.normal[1];
    const double push = stiffness * a.overlap - damping * normal_rate;
    pa.force[0] -= push * a.normal[0];
    pa.force[1] -= push * a.normal[1];
    if (pb != nullptr) {
      pb->force[0] += push * a.normal[0];
      pb->force[1] += push * a.normal[1];
    }
  }
}

void ContactSubcycler::kick_and_drift(double dt, double time, double& work) {
  for (Point& p : points_) {
    for (int c = 0; c < 2; ++c) {
      // Symplectic Euler for the contact force, the slow force a + r t integrated exactly.
      const double a = p.slow_acceleration[c], r = p.slow_rate[c], f = p.force[c] * p.inverse_mass;
      p.position[c] += dt * p.velocity[c] + dt * dt * (0.5 * a + r * (0.5 * time + dt / 6.0) + f);
      p.velocity[c] += dt * (a + r * (time + 0.5 * dt) + f);
    }
    work += dt * (p.force[0]*p.velocity[0] + p.force[1]*p.velocity[1]);
  }
}

void ContactSubcycler::move_off_list(const BodyMask& members, std::vector<MassSpringBody>& bodies, double dt_inner,
                                     int from, int to) {
  const double span = (to - from) * dt_inner, start = from * dt_inner;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!selected(members, b)) continue;
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

std::array<double, 2> ContactSubcycler::fastest(const BodyMask& members, const std::vector<MassSpringBody>& bodies,
                                                bool off_list_only) const {
  std::array<double, 2> largest{0.0, 0.0};  // squared speed, squared slow acceleration
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!selected(members, b)) continue;
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
                                                const BodyMask& members, std::vector<MassSpringBody>& bodies,
                                                bool continues, const std::vector<double>& diameter_rate) {
  if (n_inner < 1) throw std::invalid_argument("ContactSubcycler: n_inner must be >= 1");
  if (external_force.size() != bodies.size()) throw std::invalid_argument("ContactSubcycler: one force vector per body");
  ContactSubcycleResult result;
  pair_checks_ = 0;
  // Index of every point (sized once for the scene; entries are -1 outside a list).
  offset_.resize(bodies.size() + 1);
  offset_[0] = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) offset_[b + 1] = offset_[b] + bodies[b].n_points();
  if (static_cast<int>(slot_.size()) != offset_.back()) {
    slot_.assign(offset_.back(), -1);
    // Room for every point of the scene and many pairs each: no growth inside later steps.
    points_.reserve(offset_.back());
    pairs_.reserve(8 * offset_.back());
    search_.pairs.reserve(8 * offset_.back());
    walls_.reserve(2 * offset_.back());
    active_.reserve(10 * offset_.back());
    shares_.reserve(8 * bodies.size() + 8);  // body pairs and body-wall pairs in touch
    projection_.reserve(8 * bodies.size() + 8);
    spheres_.centre.reserve(offset_.back());
    spheres_.radius.reserve(offset_.back());
    spheres_.body.reserve(offset_.back());
    spheres_.point.reserve(offset_.back());
  }
  slow_.resize(bodies.size());
  spring_.resize(bodies.size());
  rate_.resize(bodies.size());
  previous_slow_.resize(bodies.size());
  radius_rate_.assign(bodies.size(), 0.0);
  if (!diameter_rate.empty() && model.cds_radius == 0.0)
    for (std::size_t b = 0; b < bodies.size(); ++b) radius_rate_[b] = model.cds_radius_fraction * diameter_rate[b];
  double smallest_radius = HUGE_VAL;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!selected(members, b)) continue;
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
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (selected(members, b)) growth = std::max(growth, std::abs(radius_rate_[b]));
  const double dt_inner = dt_outer / n_inner;
  // Skin for the time left: the travel bound V T + A T^2 / 2 of a point without contact.
  const auto travel = [](const std::array<double, 2>& largest, double time) {
    return largest[0] * time + 0.5 * largest[1] * time * time;
  };
  double skin = std::max(2.0 * skin_travel_factor * (travel(fastest(members, bodies, false), dt_outer) + growth * dt_outer),
                         skin_floor);
  build_list(model, box, skin, members, bodies, 0.0);
  result.list_builds = 1;
  std::array<double, 2> off_list = fastest(members, bodies, /*off_list_only=*/true);
  int step_built = 0;   // inner step at which the list was built
  int step_synced = 0;  // inner step the off-list points' stored state belongs to
  for (int j = 0; j < n_inner && !points_.empty(); ++j) {
    if (j > step_built) {
      // The list holds while no two points can have closed the skin since it was built.
      double moved_squared = 0.0;
      for (const Point& p : points_) {
        const double dx = p.position[0] - p.anchor[0], dy = p.position[1] - p.anchor[1];
        moved_squared = std::max(moved_squared, dx*dx + dy*dy);
      }
      const double moved = std::max(std::sqrt(moved_squared), travel(off_list, (j - step_built) * dt_inner)) +
                           growth * (j - step_built) * dt_inner;
      if (2.0 * moved >= skin) {
        // Every point to this inner step, then a new list for the time left.
        move_off_list(members, bodies, dt_inner, step_synced, j);
        step_synced = j;
        release_list(bodies);
        skin = std::max(2.0 * skin_travel_factor *
                            (travel(fastest(members, bodies, false), dt_outer - j * dt_inner) + growth * (dt_outer - j * dt_inner)),
                        skin_floor);
        build_list(model, box, skin, members, bodies, j * dt_inner);
        ++result.list_builds;
        off_list = fastest(members, bodies, true);
        step_built = j;
        if (points_.empty()) break;
      }
    }
    contact_forces(model, j * dt_inner, result.stats);
    kick_and_drift(dt_inner, j * dt_inner, result.work);
    ++result.inner_steps;
  }
  move_off_list(members, bodies, dt_inner, step_synced, n_inner);
  release_list(bodies);
  // Step 4: U += dt (F_s(x^{k+1}, U*) - F_s(x^k, U^k) - dt r) / (2 m): the velocity change over
  // the step becomes dt (F^k + F^{k+1}) / (2 m), what the extrapolated rate r gave taken back.
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!selected(members, b)) continue;
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
