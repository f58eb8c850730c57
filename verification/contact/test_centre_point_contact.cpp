// The centre point's CDS (contact.centre_point, docs/method.md §1.9), with no fluid.
//  - Forces: a wheel whose centre point lies within r_c of a wall, its rim points farther, feels a
//    wall force on its centre point alone with the option and none without; a centre point within
//    2 r_c of another wheel's rim point takes an equal and opposite pair force with the option and
//    none without; rim-only contacts are the same with and without it.
//  - Motion: a soft wheel (k_s = 0.1) whose centre point alone moves towards a wall at 6 (its rim at
//    rest, 0.2 D from the wall) passes through the wall without the option, in the shared sub-step
//    and in the contacts' inner loop; with the option it stays in the box in both and comes back.
#define BOOST_TEST_MODULE centre_point_contact
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/body_substep.hpp"
#include "contact/contact_forces.hpp"
#include "contact/contact_subcycle.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

constexpr double wall_x = 0.7;  // right wall; the rim (D = 1 about the origin) reaches x = 0.5
const WallBox box{{-2.0, -2.0}, {2.0 + wall_x, 4.0}, {false, false}};

ContactModel model_with(bool centre_point) {
  ContactModel model = make_contact_model(1.0, 0.05);  // r_c = 0.05: the rim stays clear of the wall
  model.centre_point = centre_point;
  return model;
}

std::vector<std::vector<std::array<double, 2>>> zero_forces(const std::vector<MassSpringBody>& bodies) {
  std::vector<std::vector<std::array<double, 2>>> f;
  for (const auto& body : bodies) f.emplace_back(body.n_points(), std::array<double, 2>{0.0, 0.0});
  return f;
}

double norm(const std::array<double, 2>& v) { return std::hypot(v[0], v[1]); }

// Largest x of the centre point over `duration`, and its velocity at the end.
struct CentreTrack {
  double max_x = -HUGE_VAL;
  double final_velocity_x = 0.0;
};

CentreTrack push_centre_to_wall(bool centre_point, ContactStepping stepping) {
  const ContactModel model = model_with(centre_point);
  std::vector<MassSpringBody> bodies = {make_wheel({0.0, 0.0}, {0.0, 0.0}, 0.1 / contact_stiffness)};
  MassSpringBody& wheel = bodies[0];
  wheel.velocity[wheel.centre_index()] = {6.0, 0.0};
  const double contact_dt = contact_substep(model, bodies);
  const double spring_dt = stable_substep(wheel);
  const auto frozen = zero_forces(bodies);
  ContactSubcycler subcycler;
  CentreTrack track;
  const double duration = 0.25;  // the rim drifts 0.06 with the centre point's momentum: clear of the wall
  if (stepping == ContactStepping::inner_loop) {
    // Outer steps of at most 1e-3 (the centre point moves 0.006 in one), so that its track is sampled finely.
    const double outer = std::min(model.outer_step_fraction * spring_dt, 1e-3);
    const int n_inner = static_cast<int>(std::ceil(outer / contact_dt));
    BOOST_TEST_REQUIRE(n_inner >= 2);  // the inner loop does the contact work
    for (long k = 0; k * outer < duration; ++k) {
      advance_bodies_inner_loop(model, box, outer, n_inner, frozen, bodies, subcycler, k > 0);
      track.max_x = std::max(track.max_x, wheel.position[wheel.centre_index()][0]);
    }
  } else {
    const double dt = std::min(contact_dt, spring_dt);
    for (long k = 0; k * dt < duration; ++k) {
      advance_bodies_substep(model, box, dt, frozen, bodies);
      track.max_x = std::max(track.max_x, wheel.position[wheel.centre_index()][0]);
    }
  }
  track.final_velocity_x = wheel.velocity[wheel.centre_index()][0];
  return track;
}

}  // namespace

BOOST_AUTO_TEST_CASE(centre_point_feels_walls_and_other_bodies_only_with_the_option) {
  // Wall: the centre point moved to 0.03 from the wall (r_c = 0.05), every rim point 0.1 away or more.
  std::vector<MassSpringBody> one = {make_wheel({0.0, 0.0}, {0.0, 0.0}, 1.0)};
  one[0].position[one[0].centre_index()] = {wall_x - 0.03, 0.0};
  for (const bool option : {false, true}) {
    auto force = zero_forces(one);
    add_contact_forces(model_with(option), one, box, force);
    for (int p = 0; p < one[0].n_surface; ++p) BOOST_TEST(norm(force[0][p]) == 0.0);
    const std::array<double, 2> f = force[0][one[0].centre_index()];
    if (option) {
      BOOST_TEST(f[0] < 0.0);  // pushed back into the box
      BOOST_TEST(f[0] == -contact_stiffness * 0.02, boost::test_tools::tolerance(1e-12));  // k delta, e_D = 1
    } else {
      BOOST_TEST(norm(f) == 0.0);
    }
  }
  // Pair: wheel B's rim point 0 moved to 0.07 from wheel A's centre point (2 r_c = 0.1); every other
  // rim point of either wheel farther than 0.1 from any CDS of the other.
  std::vector<MassSpringBody> two = {make_wheel({-1.0, 0.0}, {0.0, 0.0}, 1.0),
                                     make_wheel({-1.0, 1.2}, {0.0, 0.0}, 1.0)};
  two[1].position[0] = {-1.0 + 0.07, 0.0};
  for (const bool option : {false, true}) {
    auto force = zero_forces(two);
    add_contact_forces(model_with(option), two, box, force);
    const std::array<double, 2> fa = force[0][two[0].centre_index()];
    const std::array<double, 2> fb = force[1][0];
    if (option) {
      BOOST_TEST(fa[0] == -contact_stiffness * 0.03, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(fb[0] == -fa[0]);
      BOOST_TEST(fb[1] == -fa[1]);
    } else {
      BOOST_TEST(norm(fa) == 0.0);
      BOOST_TEST(norm(fb) == 0.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(centre_point_stays_in_the_box_with_the_option) {
  BOOST_TEST_MESSAGE("stepping  option  max x of the centre point (wall at " << wall_x << ")  final u");
  for (const ContactStepping stepping : {ContactStepping::shared, ContactStepping::inner_loop}) {
    const CentreTrack off = push_centre_to_wall(false, stepping);
    const CentreTrack on = push_centre_to_wall(true, stepping);
    const char* name = stepping == ContactStepping::shared ? "shared" : "inner_loop";
    BOOST_TEST_MESSAGE(name << "  off  " << off.max_x << "  " << off.final_velocity_x);
    BOOST_TEST_MESSAGE(name << "  on   " << on.max_x << "  " << on.final_velocity_x);
    BOOST_TEST(off.max_x > wall_x);   // the papers' CDS on the rim alone let the centre point out
    BOOST_TEST(on.max_x < wall_x);    // its own CDS keeps it in the box
    BOOST_TEST(on.max_x > wall_x - 0.05);  // it did reach the wall's contact range
    BOOST_TEST(on.final_velocity_x < 0.0);  // and came back
  }
}
