// The neighbour list of the contacts' inner loop (contact_subcycle.hpp, step 1): the candidate
// points, copied into contiguous arrays, and the pairs and walls within the skin, each with its
// law's stiffness and dashpot and the share its dashpot is divided in; back into the bodies when
// the list is released.
#include "contact/contact_subcycle.hpp"

#include <algorithm>
#include <cmath>

#include "contact/normal_contact_law.hpp"
#include "solid/spring_dashpot.hpp"

namespace ibms {

namespace {

// The superset of the list's pairs reaches this fraction of the smallest CDS radius beyond the
// skin (or twice the skin, if that is more): at rest the skin is a tenth of the radius, so a
// superset serves until some point has moved an eighth of the radius.
constexpr double superset_margin_fraction = 0.25;

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

// A pair that touches now with the list's skin s had, when the superset was made with reach S, a
// gap below s + 2 D (D the largest centre displacement since): the superset holds it while
// s + 2 D <= S. Growing radii (swelling) take a new search every time.
void ContactSubcycler::find_list_pairs(const WallBox& box, double skin, bool growing) {
  PairSuperset& kept = superset_;
  const int n = spheres_.n_spheres();
  bool holds = kept.valid && !growing && static_cast<int>(kept.anchor.size()) == n && skin < kept.reach;
  double moved_squared = 0.0;
  for (int s = 0; holds && s < n; ++s) {
    holds = spheres_.body[s] == kept.body[s] && spheres_.point[s] == kept.point[s];
    const std::array<double, 2> d = separation(kept.anchor[s], spheres_.centre[s], box);
    moved_squared = std::max(moved_squared, d[0]*d[0] + d[1]*d[1]);
  }
  if (!(holds && skin + 2.0 * std::sqrt(moved_squared) <= kept.reach)) {
    // A new superset: the spheres grown by half the wider reach, the search, the radii back.
    double smallest = HUGE_VAL;
    for (double r : spheres_.radius) smallest = std::min(smallest, r - 0.5 * skin);
    const double reach = skin + std::max(skin, superset_margin_fraction * smallest);
    const double grow = 0.5 * (reach - skin);
    kept_radius_.assign(spheres_.radius.begin(), spheres_.radius.end());  // restored exactly below
    for (double& r : spheres_.radius) r += grow;
    find_touching_pairs_body_bounds(spheres_, box, kept.search);
    spheres_.radius.assign(kept_radius_.begin(), kept_radius_.end());
    kept.anchor.assign(spheres_.centre.begin(), spheres_.centre.end());
    kept.body.assign(spheres_.body.begin(), spheres_.body.end());
    kept.point.assign(spheres_.point.begin(), spheres_.point.end());
    kept.reach = reach;
    kept.valid = !growing;
    pair_checks_ += kept.search.n_pair_checks;
  }
  keep_touching_pairs(spheres_, box, kept.search.pairs, search_);
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
  const double zeta = damping_ratio_from_restitution(model.restitution_coefficient);
  // Pairs of different bodies closer than the skin: the pair search on CDS grown by s / 2.
  gather_contact_spheres(model, bodies, spheres_, members);
  for (int s = 0; s < spheres_.n_spheres(); ++s) spheres_.radius[s] += time * radius_rate_[spheres_.body[s]];
  const bool several_bodies = std::any_of(spheres_.body.begin(), spheres_.body.end(),
                                          [&](int b) { return b != spheres_.body.front(); });
  if (several_bodies) {
    for (double& r : spheres_.radius) r += half_skin;
    const bool growing = std::any_of(spheres_.body.begin(), spheres_.body.end(),
                                     [&](int b) { return radius_rate_[b] != 0.0; });
    find_list_pairs(box, skin, growing);
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
      pair.damping = dashpot_constant(zeta, m_eff, pair.stiffness);
      pair.share = shares_.index(contact_group_key(body_s, body_t));
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
      for_each_point_near_walls(bodies[b].position, model.cds_points(bodies[b]), box, radius, half_skin,
                                [&](int k, int c, int side, double /*distance*/) {
                                  Wall wall;
                                  wall.a = candidate(b, k, bodies);
                                  wall.axis = c;
                                  wall.side = side;
                                  wall.radius = radius;
                                  wall.radius_rate = radius_rate_[b];
                                  wall.coordinate = side == 0 ? box.origin[c] : box.origin[c] + box.length[c];
                                  const double m_eff = contact_effective_mass(model, bodies, b, k, -1, 0);
                                  wall.stiffness = model.pair_stiffness(m_eff);
                                  wall.damping = dashpot_constant(zeta, m_eff, wall.stiffness);
                                  wall.share = shares_.index(wall_group_key(b, 2 * c + side));
                                  walls_.push_back(wall);
                                });
    }
  }
  share_factor_.resize(static_cast<std::size_t>(shares_.size()));
}


}  // namespace ibms
