// The test that lets a step skip the contact sub-step bound (contact_possible_within) is
// conservative: it answers "possible" for bodies whose contact spheres are within the reach of one
// step, including across periodic boundaries when the bodies have drifted periods apart, walls,
// and a body inside a prescribed container; and "not possible" for bodies far apart at rest. The
// groups of many bodies (found through a hash of the bodies' circles) are those that the pair test
// of every two bodies alone gives.
#define BOOST_TEST_MODULE contact_possible
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <numeric>
#include <random>

#include "contact/contact_model.hpp"
#include "solid/mass_spring_body.hpp"

using namespace ibms;

namespace {

MassSpringBody disk(std::array<double, 2> centre, double diameter, BodyKind kind = BodyKind::rigid) {
  BodyParameters spec;
  spec.kind = kind;
  spec.centre = centre;
  spec.diameter = diameter;
  spec.n_surface_points = 24;
  spec.density = 2.0;
  return build_body(spec, /*fluid_density=*/1.0);
}

ContactModel model() {
  ContactModel model;
  model.stiffness = 1e4;
  model.cds_radius = 0.01;
  model.check();
  return model;
}

}  // namespace

BOOST_AUTO_TEST_CASE(bodies_far_apart_at_rest_cannot_touch_and_near_ones_can) {
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  const std::vector<double> no_extra{0.0, 0.0};
  BOOST_TEST(!contact_possible_within(model(), {disk({0.3, 0.5}, 0.2), disk({0.7, 0.5}, 0.2)}, box, 0.01, no_extra));
  // Rims 0.015 apart: the spheres (radius 0.01) overlap already.
  BOOST_TEST(contact_possible_within(model(), {disk({0.3, 0.5}, 0.2), disk({0.515, 0.5}, 0.2)}, box, 0.01, no_extra));
  // Near a wall.
  BOOST_TEST(contact_possible_within(model(), {disk({0.11, 0.5}, 0.2), disk({0.7, 0.5}, 0.2)}, box, 0.01, no_extra));
}

BOOST_AUTO_TEST_CASE(moving_bodies_within_reach_of_one_step_can_touch) {
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  std::vector<MassSpringBody> bodies{disk({0.3, 0.5}, 0.2), disk({0.6, 0.5}, 0.2)};  // rims 0.1 apart
  const std::vector<double> no_extra{0.0, 0.0};
  BOOST_TEST(!contact_possible_within(model(), bodies, box, 0.01, no_extra));
  for (auto& u : bodies[0].velocity) u = {3.0, 0.0};  // 2 x 3 x 0.01 = 0.06 of travel ...
  BOOST_TEST(!contact_possible_within(model(), bodies, box, 0.01, no_extra));
  for (auto& u : bodies[0].velocity) u = {5.0, 0.0};  // ... 0.10: within reach
  BOOST_TEST(contact_possible_within(model(), bodies, box, 0.01, no_extra));
  // The caller's extra reach (acceleration, swelling) counts too.
  for (auto& u : bodies[0].velocity) u = {0.0, 0.0};
  BOOST_TEST(contact_possible_within(model(), bodies, box, 0.01, std::vector<double>{0.05, 0.05}));
}

BOOST_AUTO_TEST_CASE(periodic_neighbours_are_found_however_many_periods_apart) {
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {true, true}};
  const std::vector<double> no_extra{0.0, 0.0};
  // Centres 2.21 apart in x: the nearest images are 0.21 apart, the rims 0.01.
  BOOST_TEST(contact_possible_within(model(), {disk({0.3, 0.5}, 0.2), disk({2.51, 0.5}, 0.2)}, box, 0.01, no_extra));
  BOOST_TEST(contact_possible_within(model(), {disk({0.3, 0.5}, 0.2), disk({-1.91, 0.5}, 0.2)}, box, 0.01, no_extra));
  BOOST_TEST(!contact_possible_within(model(), {disk({0.3, 0.5}, 0.2), disk({2.8, 0.5}, 0.2)}, box, 0.01, no_extra));
}

BOOST_AUTO_TEST_CASE(a_body_near_the_rim_of_its_prescribed_container_can_touch_it) {
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  const std::vector<double> no_extra{0.0, 0.0};
  const MassSpringBody container = disk({0.5, 0.5}, 0.8, BodyKind::prescribed);
  BOOST_TEST(!contact_possible_within(model(), {container, disk({0.5, 0.5}, 0.2)}, box, 0.01, no_extra));
  BOOST_TEST(contact_possible_within(model(), {container, disk({0.79, 0.5}, 0.2)}, box, 0.01, no_extra));
}

// Contact groups (multi-rate sub-steps): bodies joined through a chain of pairs that may
// touch form one group, whatever the order of the bodies; a group touches if a pair in it or one
// of its bodies and a wall may; groups are numbered by their lowest body.
BOOST_AUTO_TEST_CASE(groups_join_chains_of_close_pairs_and_keep_far_bodies_apart) {
  const WallBox box{{0.0, 0.0}, {2.0, 1.0}, {false, false}};
  // 0 and 3 close (rims 0.015 apart), 3 and 1 close, 2 alone in the middle, 4 alone near a wall.
  const std::vector<MassSpringBody> bodies{disk({0.3, 0.5}, 0.2),  disk({0.73, 0.5}, 0.2), disk({1.3, 0.5}, 0.2),
                                           disk({0.515, 0.5}, 0.2), disk({1.89, 0.5}, 0.2)};
  const std::vector<double> no_extra(bodies.size(), 0.0);
  ContactGroups groups;
  find_contact_groups(model(), bodies, box, 0.01, no_extra, groups);
  BOOST_TEST(groups.n_groups == 3);
  BOOST_TEST(groups.group_of == (std::vector<int>{0, 0, 1, 0, 2}), boost::test_tools::per_element());
  BOOST_TEST(groups.may_touch == (std::vector<char>{1, 0, 1}), boost::test_tools::per_element());
  BOOST_TEST(groups.any_contact());
  // Reused: far apart, each body its own group, nothing to touch.
  const std::vector<MassSpringBody> apart{disk({0.3, 0.5}, 0.2), disk({1.0, 0.5}, 0.2), disk({1.6, 0.5}, 0.2)};
  find_contact_groups(model(), apart, box, 0.01, std::vector<double>(3, 0.0), groups);
  BOOST_TEST(groups.n_groups == 3);
  BOOST_TEST(groups.group_of == (std::vector<int>{0, 1, 2}), boost::test_tools::per_element());
  BOOST_TEST(!groups.any_contact());
  // Contacts off: groups of one, never touching, even for overlapping bodies.
  find_contact_groups(ContactModel{}, bodies, box, 0.01, no_extra, groups);
  BOOST_TEST(groups.n_groups == 5);
  BOOST_TEST(!groups.any_contact());
}

BOOST_AUTO_TEST_CASE(a_chain_listed_backwards_is_one_group) {
  // 4 - 3 - 2 - 1 - 0 touching in a row, listed so that each union joins two existing roots.
  const WallBox box{{0.0, 0.0}, {3.0, 1.0}, {false, false}};
  std::vector<MassSpringBody> bodies;
  const double x[] = {0.5, 1.38, 0.72, 1.16, 0.94};  // 0 - 2 - 4 - 3 - 1 along x, 0.02 gaps
  for (double xc : x) bodies.push_back(disk({xc, 0.5}, 0.2));
  ContactGroups groups;
  find_contact_groups(model(), bodies, box, 0.01, std::vector<double>(bodies.size(), 0.0), groups);
  BOOST_TEST(groups.n_groups == 1);
  BOOST_TEST(groups.group_of == (std::vector<int>(5, 0)), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(the_groups_of_many_bodies_are_those_of_every_pair) {
  // 120 disks of two sizes moving at random in a box (walls, or periodic with bodies periods
  // away), some with an extra reach, and a prescribed container holding part of them: each pair's
  // link and each body's wall contact from find_contact_groups on that pair or body alone, joined
  // into components, against the groups of all bodies at once.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const bool periodic : {false, true}) {
    const WallBox box{{0.0, 0.0}, {3.0, 2.0}, {periodic, periodic}};
    std::vector<MassSpringBody> bodies;
    std::vector<double> extra;
    bodies.push_back(disk({1.0, 1.0}, 1.2, BodyKind::prescribed));
    extra.push_back(0.0);
    for (int k = 0; k < 120; ++k) {
      const double shift = periodic && k % 7 == 0 ? 3.0 : 0.0;  // drifted a period away
      MassSpringBody body = disk({3.0 * uniform(random) + shift, 2.0 * uniform(random)}, k % 4 == 0 ? 0.15 : 0.1);
      for (auto& v : body.velocity) v = {2.0 * uniform(random) - 1.0, 2.0 * uniform(random) - 1.0};
      bodies.push_back(body);
      extra.push_back(k % 5 == 0 ? 0.05 : 0.0);
    }
    const std::size_t n = bodies.size();
    const double dt = 0.01;
    ContactGroups all;
    find_contact_groups(model(), bodies, box, dt, extra, all);
    // The oracle: components of the pairwise links.
    std::vector<int> root(n);
    std::iota(root.begin(), root.end(), 0);
    const auto find = [&](int b) {
      while (root[b] != b) b = root[b];
      return b;
    };
    std::vector<char> touches(n, 0);
    int links = 0;
    for (std::size_t a = 0; a < n; ++a) {
      ContactGroups one;
      find_contact_groups(model(), {bodies[a]}, box, dt, {extra[a]}, one);
      if (one.any_contact()) touches[a] = 1;
      for (std::size_t b = a + 1; b < n; ++b) {
        ContactGroups pair;
        find_contact_groups(model(), {bodies[a], bodies[b]}, box, dt, {extra[a], extra[b]}, pair);
        if (pair.n_groups != 1) continue;
        ++links;
        touches[a] = touches[b] = 1;
        const int ra = find(static_cast<int>(a)), rb = find(static_cast<int>(b));
        root[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
    BOOST_TEST_MESSAGE((periodic ? "periodic" : "walls") << ": " << links << " linked pairs, " << all.n_groups
                                                         << " groups");
    BOOST_TEST(links > 20);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        BOOST_TEST((all.group_of[a] == all.group_of[b]) == (find(static_cast<int>(a)) == find(static_cast<int>(b))));
    for (std::size_t a = 0; a < n; ++a) BOOST_TEST(static_cast<bool>(all.may_touch[all.group_of[a]]) >= static_cast<bool>(touches[a]));
    for (int g = 0; g < all.n_groups; ++g) {
      bool any = false;
      for (std::size_t a = 0; a < n; ++a)
        if (all.group_of[a] == g) any = any || touches[a];
      BOOST_TEST(static_cast<bool>(all.may_touch[g]) == any);
    }
  }
}

BOOST_AUTO_TEST_CASE(prescribed_bodies_alone_form_their_own_groups) {
  // No free body: the hash of free bodies is empty and its cells are as small as they get.
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  ContactGroups groups;
  find_contact_groups(model(), {disk({0.3, 0.5}, 0.2, BodyKind::prescribed), disk({0.52, 0.5}, 0.2, BodyKind::prescribed)},
                      box, 0.01, {0.0, 0.0}, groups);
  BOOST_TEST(groups.n_groups == 2);
  BOOST_TEST(!groups.any_contact());
}
