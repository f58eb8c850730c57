// Head-on collisions of two stiff wheels, and of a wheel with a wall, with no fluid rebound with
// the restitution coefficient e_D of the contact (docs/method.md §1.9, §A8), measured on the
// centre-of-mass velocities. The wheels are stiff: springs 1000 k_Dn, so the wheel modes are far
// above the contact frequency sqrt(S k_Dn / m_eff) and the body rebounds as a rigid one (a
// compliant wheel in series softens the contact, lowers its damping ratio and raises e; the error
// falls like k_Dn / k_s, see restitution_error_falls_with_wheel_stiffness). Rim point 0 of the
// left wheel meets rim point 10 of the right one: one CDS pair engages (CDS radius 0.05 D; the
// neighbours would need an overlap of 0.049 D). Turned by pi/N_l with the two-sided cavity's CDS
// radius 0.167 D, the right wheel offers two nearly parallel pairs.
// With IBMS_RESULTS_DIR set (ctest), the restitution tables go to restitution.csv, the histories
// through each contact (thinned to at most 300 rows) to contact_history.csv and the e = 1 energy
// table to restitution_elastic.csv for the report (verification/common/results_csv.hpp).
#define BOOST_TEST_MODULE wheel_restitution
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

constexpr double stiff_ratio = 1000.0;  // k_s / k_Dn of the "stiff" wheels [-]
const WallBox open_box{{-10.0, -10.0}, {20.0, 20.0}, {false, false}};  // walls far away
const WallBox near_wall_box{{-1.0, -1.0}, {1.9, 2.0}, {false, false}};  // right wall at x = 0.9

CollisionRecord wheel_pair(double restitution, double ratio = stiff_ratio, double turn = 0.0,
                           double cds_fraction = 0.05) {
  const double half_gap = 0.5 + cds_fraction + 0.05;  // CDS 0.1 apart at the start
  return collide(make_contact_model(restitution, cds_fraction), open_box,
                 {make_wheel({-half_gap, 0.0}, {0.5*impact_speed, 0.0}, ratio),
                  make_wheel({half_gap, 0.0}, {-0.5*impact_speed, 0.0}, ratio, turn)});
}

CollisionRecord wheel_on_wall(double restitution, double ratio = stiff_ratio) {
  return collide(make_contact_model(restitution), near_wall_box,
                 {make_wheel({0.3, 0.0}, {impact_speed, 0.0}, ratio)});
}

double kinetic_energy_of_centres(const std::vector<MassSpringBody>& bodies,
                                 const std::vector<std::array<double, 2>>& velocity) {
  double energy = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    energy += 0.5 * bodies[b].total_mass() * (velocity[b][0]*velocity[b][0] + velocity[b][1]*velocity[b][1]);
  return energy;
}

std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void check_restitution_table(const char* title, CollisionRecord (*run)(double, double)) {
  BOOST_TEST_MESSAGE(title);
  BOOST_TEST_MESSAGE("e_target  e_measured  rel_error  max_active  steps_per_contact");
  using verification::csv_number;
  const double tolerance = 0.01;  // the target: the measured e within 1 % of e_D
  std::vector<std::string> table, history;
  for (double e : {0.1, 0.5, 0.9}) {
    const CollisionRecord r = run(e, stiff_ratio);
    const double measured = measured_restitution(r);
    const double error = std::abs(measured - e) / e;
    BOOST_TEST_MESSAGE(e << "  " << measured << "  " << error << "  " << r.max_active << "  "
                         << r.contact_time / r.substep);
    BOOST_TEST(error <= tolerance);
    const std::string key = quoted(title) + "," + csv_number(e) + ",";
    table.push_back(key + csv_number(measured) + "," + csv_number(error) + "," + csv_number(tolerance) +
                    "," + csv_number(r.contact_time / r.substep));
    // Time over the contact duration, normal relative velocity over the approach speed, overlap
    // over the diameter (1); at most 300 rows, the last one kept.
    const std::size_t n = r.history.size(), stride = std::max<std::size_t>(1, (n + 298) / 299);
    for (std::size_t k = 0; k < n; ++k) {
      if (k % stride != 0 && k + 1 != n) continue;
      const auto& h = r.history[k];
      history.push_back(key + csv_number(h[0] / r.contact_time) + "," + csv_number(h[1]) + "," +
                        csv_number(h[2]));
    }
  }
  verification::append_results_csv(
      "restitution.csv", "case,e_target,e_measured,rel_error,tolerance,steps_per_contact", table);
  verification::append_results_csv(
      "contact_history.csv",
      "case,e_target,t_over_contact_time,normal_velocity_over_approach,overlap_over_diameter", history);
}

}  // namespace

BOOST_AUTO_TEST_CASE(restitution_error_falls_with_wheel_stiffness) {
  BOOST_TEST_MESSAGE("k_s/k_Dn  e_pair  e_wall  (target 0.5)");
  double previous_pair = 1.0, previous_wall = 1.0;
  for (double ratio : {10.0, 30.0, 100.0, 300.0, 1000.0}) {
    const double pair_error = std::abs(measured_restitution(wheel_pair(0.5, ratio)) - 0.5);
    const double wall_error = std::abs(measured_restitution(wheel_on_wall(0.5, ratio)) - 0.5);
    BOOST_TEST_MESSAGE(ratio << "  " << 0.5 + pair_error << "  " << 0.5 + wall_error);
    BOOST_TEST(pair_error < previous_pair);  // claim: stiffer wheels rebound closer to e_D
    BOOST_TEST(wall_error < previous_wall);
    previous_pair = pair_error;
    previous_wall = wall_error;
  }
}

BOOST_AUTO_TEST_CASE(wheel_pair_rebounds_with_prescribed_restitution) {
  check_restitution_table("wheel-wheel, one CDS pair", [](double e, double ratio) {
    return wheel_pair(e, ratio);
  });
}

BOOST_AUTO_TEST_CASE(wheel_pair_with_two_active_pairs_rebounds_with_prescribed_restitution) {
  check_restitution_table("wheel-wheel, right wheel turned by pi/N_l, CDS 0.167 D: two CDS pairs",
                          [](double e, double ratio) { return wheel_pair(e, ratio, M_PI / 20.0, 0.167); });
}

BOOST_AUTO_TEST_CASE(wheel_rebounds_from_wall_with_prescribed_restitution) {
  check_restitution_table("wheel-wall", [](double e, double ratio) { return wheel_on_wall(e, ratio); });
}

BOOST_AUTO_TEST_CASE(elastic_collisions_conserve_kinetic_energy) {
  BOOST_TEST_MESSAGE("case  KE_before  KE_after  rel_change");
  const std::vector<MassSpringBody> pair = {make_wheel({-0.6, 0.0}, {0.0, 0.0}, stiff_ratio),
                                            make_wheel({0.6, 0.0}, {0.0, 0.0}, stiff_ratio)};
  const std::vector<MassSpringBody> single = {pair[0]};
  const CollisionRecord records[2] = {wheel_pair(1.0), wheel_on_wall(1.0)};
  const char* names[2] = {"wheel-wheel", "wheel-wall"};
  const double tolerance = 1e-3;  // the target for e = 1: within 0.1 %
  std::vector<std::string> table;
  using verification::csv_number;
  for (int c = 0; c < 2; ++c) {
    const auto& bodies = c == 0 ? pair : single;
    const double before = kinetic_energy_of_centres(bodies, records[c].velocity_before);
    const double after = kinetic_energy_of_centres(bodies, records[c].velocity_after);
    const double change = std::abs(after - before) / before;
    BOOST_TEST_MESSAGE(names[c] << "  " << before << "  " << after << "  " << change);
    BOOST_TEST(change <= tolerance);
    table.push_back(quoted(names[c]) + "," + csv_number(before) + "," + csv_number(after) + "," +
                    csv_number(change) + "," + csv_number(tolerance));
  }
  verification::append_results_csv("restitution_elastic.csv",
                                   "case,ke_before,ke_after,rel_change,tolerance", table);
}
