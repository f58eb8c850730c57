// Contact parameters, CDS radius and contact sub-step bound, docs/method.md §1.9, §5.1 and A8.
#include "contact/contact_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/cell_hash.hpp"
#include "core/constants.hpp"
#include "solid/spring_dashpot.hpp"

namespace ibms {

void ContactModel::check() const {
  if (!(stiffness >= 0.0)) throw std::invalid_argument("contact: stiffness must be >= 0");
  if (law == ContactLawKind::collision_time && (stiffness > 0.0 || !(collision_steps >= 1.0)))
    throw std::invalid_argument("contact: collision_time takes no stiffness and collision_steps >= 1");
  if (!(restitution_coefficient > 0.0 && restitution_coefficient <= 1.0))
    throw std::invalid_argument("contact: restitution_coefficient must be in (0, 1]");
  if (!(steps_per_contact >= 1.0) || !(active_pairs_safety >= 1.0))
    throw std::invalid_argument("contact: steps_per_contact and active_pairs_safety must be >= 1");
  if (!(outer_step_fraction > 0.0 && outer_step_fraction <= 1.0))
    throw std::invalid_argument("contact: outer_step_fraction must be in (0, 1]");
  if (!(cds_radius >= 0.0) || !(cds_radius_fraction >= 0.0))
    throw std::invalid_argument("contact: cds_radius and cds_radius_fraction must be >= 0");
  if (enabled() && cds_radius == 0.0 && cds_radius_fraction == 0.0)
    throw std::invalid_argument("contact: stiffness > 0 needs cds_radius or cds_radius_fraction");
}

ContactModel ContactModel::for_fluid_step(double dt) const {
  ContactModel model = *this;
  if (law == ContactLawKind::collision_time) model.collision_time = collision_steps * dt;
  return model;
}

double ContactModel::pair_stiffness(double pair_mass) const {
  if (law == ContactLawKind::linear) return stiffness;
  // t_c = sqrt(m_eff / k) sqrt(pi^2 + ln^2 e) = T_c (A8) solved for k.
  const double log_e = std::log(restitution_coefficient);
  return pair_mass * (pi * pi + log_e * log_e) / (collision_time * collision_time);
}

double ContactModel::cds_radius_of(const MassSpringBody& body) const {
  return cds_radius > 0.0 ? cds_radius : cds_radius_fraction * body.diameter;
}

double cds_point_mass(const MassSpringBody& body, int point) {
  return body.kind == BodyKind::rigid ? body.total_mass() / 3.0 : body.mass[point];
}

double lightest_cds_point_mass(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                               const BodySet& members) {
  double lightest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const MassSpringBody& body = bodies[members.at(i)];
    if (body.kind == BodyKind::prescribed) continue;  // infinitely heavy: its partner's mass counts
    for (int k = 0; k < model.cds_points(body); ++k) lightest = std::min(lightest, cds_point_mass(body, k));
  }
  return lightest;
}

namespace {

}  // namespace

ContactSubstepBounds contact_substep_bounds(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                                            const BodySet& members) {
  constexpr double dashpot_safety = 0.5;      // docs/method.md §5.3 safety factor on a stability limit
  ContactSubstepBounds bounds;
  if (!model.enabled() || bodies.empty()) return bounds;
  const double lightest_point = lightest_cds_point_mass(model, bodies, members);
  double heaviest_body = 0.0, heaviest_point = 0.0;
  std::size_t n_members = 0;
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    ++n_members;
    if (bodies[b].kind == BodyKind::prescribed) continue;
    heaviest_body = std::max(heaviest_body, bodies[b].total_mass());
    for (int k = 0; k < model.cds_points(bodies[b]); ++k) heaviest_point = std::max(heaviest_point, cds_point_mass(bodies[b], k));
  }
  if (!std::isfinite(lightest_point)) return bounds;  // prescribed only
  // Two equal lightest points in a pair have m_eff = m_p / 2; against a wall m_eff = m_p.
  const double m_eff = n_members > 1 ? 0.5 * lightest_point : lightest_point;
  const double n_active = model.active_pairs_safety;
  // The largest m_eff of a pair: the heaviest body (or point) against a wall or a prescribed body.
  const bool whole_body = model.effective_mass == ContactEffectiveMass::body;
  const double heaviest = whole_body ? heaviest_body : heaviest_point;
  // Damping of n_active pairs as add_contact_forces builds it: the heaviest body pair gives the
  // largest c in the body convention; with collision_time c grows like m_eff in both conventions.
  const double damping_mass =
      model.law == ContactLawKind::collision_time ? heaviest : (whole_body ? heaviest_body : m_eff);
  // The stiffest pair: k_Dn, or for collision_time the heaviest (k grows like m_eff).
  const double pair_k = model.pair_stiffness(heaviest);
  const double stiffness = n_active * pair_k;
  const double per_pair_stiffness = model.share_damping_among_active_pairs ? pair_k / n_active : pair_k;
  const double total_damping =
      n_active * damping_from_restitution(model.restitution_coefficient, damping_mass, per_pair_stiffness);
  // t_c = sqrt(m_eff / k) sqrt(pi^2 + ln^2 e) (A8), here from the undamped point oscillator
  // (the shortest duration; damping lengthens it).
  bounds.pair_stiffness = pair_k;
  bounds.duration = contact_duration(m_eff, stiffness, /*damping=*/0.0);
  bounds.resolution = bounds.duration / model.steps_per_contact;
  if (total_damping > 0.0) bounds.dashpot = dashpot_safety * 2.0 * lightest_point / total_damping;
  return bounds;
}

double contact_substep(const ContactModel& model, const std::vector<MassSpringBody>& bodies, const BodySet& members) {
  const ContactSubstepBounds bounds = contact_substep_bounds(model, bodies, members);
  return std::min(bounds.resolution, bounds.dashpot);
}

double contact_dashpot_substep(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                               const BodySet& members) {
  return contact_substep_bounds(model, bodies, members).dashpot;
}

namespace {

struct BoundingCircle {
  std::array<double, 2> centre{0.0, 0.0};  // [length]
  double radius = 0.0;                     // holds every CDS point and its CDS [length]
  double speed = 0.0;                      // largest point speed [length/time]
};

BoundingCircle bounding_circle(const ContactModel& model, const MassSpringBody& body) {
  BoundingCircle circle;
  for (int k = 0; k < body.n_surface; ++k)
    for (int d = 0; d < 2; ++d) circle.centre[d] += body.position[k][d] / body.n_surface;
  for (int p = 0; p < body.n_points(); ++p) {
    circle.speed = std::max(circle.speed, std::hypot(body.velocity[p][0], body.velocity[p][1]));
    if (p < model.cds_points(body))
      circle.radius = std::max(circle.radius, std::hypot(body.position[p][0] - circle.centre[0],
                                                         body.position[p][1] - circle.centre[1]));
  }
  circle.radius += model.cds_radius_of(body);
  return circle;
}

}  // namespace

bool ContactGroups::any_contact() const {
  return std::any_of(may_touch.begin(), may_touch.end(), [](char touch) { return touch != 0; });
}

namespace {

int root_of(std::vector<int>& parent, int b) {
  while (parent[b] != b) b = parent[b] = parent[parent[b]];  // path halving
  return b;
}

}  // namespace

void find_contact_groups(const ContactModel& model, const std::vector<MassSpringBody>& bodies, const WallBox& box,
                         double dt, const std::vector<double>& reach_extra, ContactGroups& groups) {
  const int n_bodies = static_cast<int>(bodies.size());
  // Union-find in group_of (parents), then relabelled to 0 .. n_groups - 1.
  std::vector<int>& parent = groups.group_of;
  parent.resize(n_bodies);
  for (int b = 0; b < n_bodies; ++b) parent[b] = b;
  groups.may_touch.assign(n_bodies, 0);  // per body first, per group after relabelling
  std::vector<char>& touches = groups.may_touch;
  if (model.enabled()) {
    constexpr double travel_safety = 2.0;  // velocities change within the step; doubles the travel
    const auto reach = [&](double speed, double extra, double cds_radius) {
      return travel_safety * speed * dt + extra + 0.5 * cds_radius;
    };
    // Each body's circle once: centre, radius (rim and CDS), largest point speed, CDS radius.
    std::vector<std::array<double, 5>>& circle = groups.circles;
    circle.resize(n_bodies);
    // Over the free (not prescribed) bodies: the largest radius, travel and extra, and CDS radius;
    // a pair's reach is at most twice the largest travel and extra plus half the largest CDS radius.
    double largest_radius = 0.0, largest_travel = 0.0, largest_cds = 0.0;
    for (int b = 0; b < n_bodies; ++b) {
      const BoundingCircle c = bounding_circle(model, bodies[b]);
      circle[b] = {c.centre[0], c.centre[1], c.radius, c.speed, model.cds_radius_of(bodies[b])};
      if (bodies[b].kind == BodyKind::prescribed) continue;
      largest_radius = std::max(largest_radius, c.radius);
      largest_travel = std::max(largest_travel, reach(c.speed, reach_extra[b], 0.0));
      largest_cds = std::max(largest_cds, circle[b][4]);
    }
    const double largest_reach = 2.0 * largest_travel + 0.5 * largest_cds;
    // The pair test of bodies a and b: their circles closer than the reach (a body inside a
    // prescribed container, a regular polygon with all rim points at one radius, is close whenever
    // it nears the container's rim).
    const auto test_pair = [&](int a, int b) {
      if (bodies[a].kind == BodyKind::prescribed && bodies[b].kind == BodyKind::prescribed) return;
      const auto& ca = circle[a];
      const auto& cb = circle[b];
      double distance_squared = 0.0;
      for (int d = 0; d < 2; ++d) {
        double delta = ca[d] - cb[d];
        // Nearest image: bodies are not wrapped back into the box, so they may be periods apart.
        if (box.periodic[d]) delta -= box.length[d] * std::round(delta / box.length[d]);
        distance_squared += delta * delta;
      }
      const double distance = std::sqrt(distance_squared);
      const bool a_contains_b = bodies[a].kind == BodyKind::prescribed && distance + cb[2] <= ca[2];
      const bool b_contains_a = bodies[b].kind == BodyKind::prescribed && distance + ca[2] <= cb[2];
      const double gap = a_contains_b || b_contains_a
                             ? std::max(ca[2], cb[2]) - distance - std::min(ca[2], cb[2]) - 2.0 * std::max(ca[4], cb[4])
                             : distance - ca[2] - cb[2];
      if (gap < reach(ca[3] + cb[3], reach_extra[a] + reach_extra[b], std::min(ca[4], cb[4]))) {
        touches[a] = touches[b] = 1;
        const int ra = root_of(parent, a), rb = root_of(parent, b);
        if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);  // the lowest index is the root
      }
    };
    for (int a = 0; a < n_bodies; ++a) {
      if (!model.walls || bodies[a].kind == BodyKind::prescribed) continue;
      for (int d = 0; d < 2; ++d) {
        if (box.periodic[d]) continue;
        const auto& ca = circle[a];
        const double gap = std::min(box.is_wall(d, 0) ? ca[d] - ca[2] - box.origin[d] : HUGE_VAL,
                                    box.is_wall(d, 1) ? box.origin[d] + box.length[d] - ca[d] - ca[2] : HUGE_VAL);
        if (gap < reach(ca[3], reach_extra[a], ca[4])) touches[a] = 1;
      }
    }
    // Prescribed bodies (containers, obstacles, any size) against every body; the free bodies
    // against each other through a hash of their centres in cells of side 2 R + reach (R the
    // largest free circle), so that a pair within reach sits in the same or neighbouring cells.
    // The partition does not depend on the order of the unions: roots are the lowest index.
    for (int a = 0; a < n_bodies; ++a)
      if (bodies[a].kind == BodyKind::prescribed)
        for (int b = 0; b < n_bodies; ++b)
          if (b != a) test_pair(std::min(a, b), std::max(a, b));
    const double cell = std::max(2.0 * largest_radius + largest_reach, std::numeric_limits<double>::min());
    for_each_near_pair(
        n_bodies, [&](int b) { return std::array<double, 2>{circle[b][0], circle[b][1]}; },
        [&](int b) { return bodies[b].kind != BodyKind::prescribed; }, box.origin, box.length, box.periodic, cell,
        groups.hashed, test_pair);
  }
  // Every parent has a lower index than its child (unions point to the lower root, path halving
  // to an ancestor), so one ascending pass makes each entry its root, and a second relabels the
  // roots 0, 1, ... in order. touches[] is per body until its slot is reused per group: slots
  // written while relabelling body b are <= b, so a later body's own entry is still intact.
  for (int b = 0; b < n_bodies; ++b) parent[b] = parent[parent[b]];
  groups.n_groups = 0;
  for (int b = 0; b < n_bodies; ++b) {
    if (parent[b] == b) {
      const char touch = touches[b];
      parent[b] = groups.n_groups;
      touches[groups.n_groups] = touch;
      ++groups.n_groups;
    } else {
      const char touch = touches[b];
      parent[b] = parent[parent[b]];  // the root, relabelled already
      if (touch) touches[parent[b]] = 1;
    }
  }
  touches.resize(groups.n_groups);
}

bool contact_possible_within(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                             const WallBox& box, double dt, const std::vector<double>& reach_extra) {
  ContactGroups groups;
  find_contact_groups(model, bodies, box, dt, reach_extra, groups);
  return groups.any_contact();
}

}  // namespace ibms
