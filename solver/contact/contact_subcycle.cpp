// The outer step of the contacts' multiple time stepping (contact_subcycle.hpp): the slow forces,
// the skin, the segments of inner steps and the lists they need, the springs' closing half-kick.
// The neighbour list is in contact_subcycle_list.cpp, the inner loop's forces and motion in
// contact_subcycle_inner_loop.cpp, the inner step's bound in contact_subcycle_step_bound.cpp.
#include "contact/contact_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solid/spring_forces.hpp"

namespace ibms {

namespace {

constexpr double skin_travel_factor = 1.5;   // s = 2 * 1.5 * V * (time left): candidates may speed up
constexpr double skin_floor_fraction = 0.1;  // s >= 0.1 r_cds: bodies at rest do not rebuild every step

}  // namespace

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
    share_factor_.reserve(8 * bodies.size() + 8);
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
