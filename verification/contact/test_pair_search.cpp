// The CDS pair search (docs/method.md §1.9): the cell list (bins >= 2 r_max) finds exactly the pairs of
// the brute-force O(n^2) search, with and without periodic directions, so does the body-box broad
// phase (the one the contact forces use; its speed is measured in bench/, not here); a scene with one body
// does no pair search at all (only wall contacts). CDS radii follow the current diameter.
#define BOOST_TEST_MODULE pair_search
#include <boost/test/unit_test.hpp>

#include <ostream>
#include <random>
#include <string>
#include <utility>

#include "contact/cds_pair_search.hpp"
#include "oracles/brute_force_pair_search.hpp"
#include "contact/contact_forces.hpp"
#include "solid/mass_spring_body.hpp"
#include "wheel_collision.hpp"

namespace ibms {
std::ostream& operator<<(std::ostream& out, const SpherePair& pair) {  // for Boost.Test messages
  return out << "(" << pair.first << ", " << pair.second << ")";
}
}  // namespace ibms

using namespace ibms;
using namespace ibms::test;

namespace {

// 3000 CDS on 40 bodies at random in the unit box, radii 0.002 to 0.02 (seeded).
ContactSpheres random_spheres() {
  std::mt19937 generator(/*seed=*/4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> body(0, 39);
  ContactSpheres spheres;
  for (int s = 0; s < 3000; ++s) {
    spheres.centre.push_back({unit(generator), unit(generator)});
    spheres.radius.push_back(0.002 + 0.018 * unit(generator));
    spheres.body.push_back(body(generator));
    spheres.point.push_back(s);
  }
  return spheres;
}

}  // namespace

BOOST_AUTO_TEST_CASE(cell_list_finds_exactly_the_brute_force_pairs) {
  const ContactSpheres spheres = random_spheres();
  BOOST_TEST_MESSAGE("periodic  pairs_cell_list  pairs_brute_force  checks_cell_list  checks_brute_force");
  for (bool periodic : {false, true}) {
    const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {periodic, periodic}};
    const PairSearchResult cells = find_touching_pairs_cell_list(spheres, box);
    const PairSearchResult brute = oracles::find_touching_pairs_brute_force(spheres, box);
    BOOST_TEST_MESSAGE(periodic << "  " << cells.pairs.size() << "  " << brute.pairs.size() << "  "
                                << cells.n_pair_checks << "  " << brute.n_pair_checks);
    BOOST_TEST(brute.pairs.size() > 100u);  // a configuration with plenty of contacts
    BOOST_TEST(cells.pairs == brute.pairs, boost::test_tools::per_element());  // exact equality
    BOOST_TEST(cells.n_pair_checks < brute.n_pair_checks / 10);  // the point of the cell list
  }
}

BOOST_AUTO_TEST_CASE(body_bounds_search_finds_exactly_the_brute_force_pairs) {
  // Random spheres (40 bodies spread over the box: their boxes overlap), and a cavity layout:
  // 16 wheels D = 0.15, CDS radius 0.167 D, on a lattice of spacing 0.22 (rim gap 0.07 > 2 r_c),
  // with wheels 1 and 6 moved 0.04 towards wheels 0 and 5 (rim gap 0.03: touching).
  const WallBox box{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  const ContactModel model = make_contact_model(1.0, 0.167);
  std::vector<MassSpringBody> bodies;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      BodyParameters spec;
      const double shift = (j * 4 + i == 1 || j * 4 + i == 6) ? -0.04 : 0.0;
      spec.centre = {0.17 + 0.22 * i + shift, 0.17 + 0.22 * j};
      spec.diameter = 0.15;
      spec.n_surface_points = 21;
      spec.density = 1.5;
      spec.spring_stiffness = 1.0;
      bodies.push_back(build_wheel(spec));
    }
  BOOST_TEST_MESSAGE("layout  pairs_bounds  pairs_brute_force  checks_bounds  checks_cell_list  checks_brute_force");
  for (const auto& [name, spheres] : {std::pair{"random", random_spheres()},
                                      std::pair{"lattice", gather_contact_spheres(model, bodies)}}) {
    const PairSearchResult bounds = find_touching_pairs_body_bounds(spheres, box);
    const PairSearchResult cells = find_touching_pairs_cell_list(spheres, box);
    const PairSearchResult brute = oracles::find_touching_pairs_brute_force(spheres, box);
    BOOST_TEST_MESSAGE(name << "  " << bounds.pairs.size() << "  " << brute.pairs.size() << "  " << bounds.n_pair_checks
                            << "  " << cells.n_pair_checks << "  " << brute.n_pair_checks);
    BOOST_TEST(brute.pairs.size() > 0u);
    BOOST_TEST(bounds.pairs == brute.pairs, boost::test_tools::per_element());  // exact equality
    // On the lattice most body boxes are disjoint: the broad phase must cull most sphere pairs.
    if (std::string(name) == "lattice") BOOST_TEST(bounds.n_pair_checks < brute.n_pair_checks / 10);
  }
}

BOOST_AUTO_TEST_CASE(cell_list_with_capped_and_few_bins_finds_the_brute_force_pairs) {
  // Tiny spheres spread over the box: floor(span / 2 r_max) = 5000 bins per axis exceeds the cap
  // (4 sqrt(n) + 1), so bins are wider than 2 r_max; and a periodic box of span 2.5 r_max: two bins,
  // where the i-1 and i+1 neighbours coincide.
  std::mt19937 generator(/*seed=*/7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ContactSpheres tiny, crowded;
  for (int s = 0; s < 400; ++s) {
    tiny.centre.push_back({unit(generator), unit(generator)});
    tiny.radius.push_back(1e-4);
    tiny.body.push_back(s % 7);
    tiny.point.push_back(s);
    crowded.centre.push_back({0.25 * unit(generator), 0.25 * unit(generator)});
    crowded.radius.push_back(0.05);
    crowded.body.push_back(s % 7);
    crowded.point.push_back(s);
  }
  // A few touching tiny pairs: copies shifted by 1e-4.
  for (int s = 0; s < 20; ++s) {
    tiny.centre.push_back({tiny.centre[s][0] + 1e-4, tiny.centre[s][1]});
    tiny.radius.push_back(1e-4);
    tiny.body.push_back((s + 1) % 7);
    tiny.point.push_back(400 + s);
  }
  const WallBox walled{{0.0, 0.0}, {1.0, 1.0}, {false, false}};
  const WallBox periodic{{0.0, 0.0}, {0.25, 0.25}, {true, true}};
  const PairSearchResult a = find_touching_pairs_cell_list(tiny, walled);
  const PairSearchResult b = oracles::find_touching_pairs_brute_force(tiny, walled);
  const PairSearchResult c = find_touching_pairs_cell_list(crowded, periodic);
  const PairSearchResult d = oracles::find_touching_pairs_brute_force(crowded, periodic);
  BOOST_TEST_MESSAGE("tiny: " << a.pairs.size() << " pairs; periodic two bins: " << c.pairs.size() << " pairs");
  BOOST_TEST(b.pairs.size() >= 20u);
  BOOST_TEST(a.pairs == b.pairs, boost::test_tools::per_element());
  BOOST_TEST(d.pairs.size() > 100u);
  BOOST_TEST(c.pairs == d.pairs, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(single_body_scene_does_no_pair_search) {
  // One wheel whose rim point 0 overlaps the right wall x = 1: a wall contact, no pair checks;
  // a second wheel far away makes the search run.
  const WallBox box{{-1.0, -1.0}, {2.0, 2.0}, {false, false}};
  const ContactModel model = make_contact_model(0.5, 0.05);
  std::vector<MassSpringBody> bodies = {make_wheel({0.47, 0.0}, {0.0, 0.0}, 10.0)};
  std::vector<std::vector<std::array<double, 2>>> force(1, std::vector<std::array<double, 2>>(21));
  const ContactStats one = add_contact_forces(model, bodies, box, force);
  bodies.push_back(make_wheel({-0.4, 0.0}, {0.0, 0.0}, 10.0));
  force.emplace_back(21, std::array<double, 2>{0.0, 0.0});
  const ContactStats two = add_contact_forces(model, bodies, box, force);
  BOOST_TEST_MESSAGE("bodies  pair_checks  wall_contacts");
  BOOST_TEST_MESSAGE("1  " << one.n_pair_checks << "  " << one.n_wall_contacts);
  BOOST_TEST_MESSAGE("2  " << two.n_pair_checks << "  " << two.n_wall_contacts);
  BOOST_TEST(one.n_pair_checks == 0);
  BOOST_TEST(one.n_wall_contacts == 1);
  BOOST_TEST(two.n_pair_checks > 0);
}

BOOST_AUTO_TEST_CASE(cds_radius_follows_current_diameter) {
  ContactModel model = make_contact_model(1.0, 0.167);
  MassSpringBody body = make_wheel({0.0, 0.0}, {0.0, 0.0}, 10.0);
  body.diameter = 1.5 * body.diameter0;  // swollen
  BOOST_TEST(model.cds_radius_of(body) == 0.167 * 1.5, boost::test_tools::tolerance(1e-15));
  model.cds_radius = 0.04;  // an absolute radius wins over the fraction
  BOOST_TEST(model.cds_radius_of(body) == 0.04);
}
