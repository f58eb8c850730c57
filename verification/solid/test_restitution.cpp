// Two mass points meeting through a linear spring-dashpot contact that acts only while they
// overlap (DEM-like, docs/method.md §1.9) rebound with the restitution coefficient the dashpot was
// built for: c = 2 zeta sqrt(m_eff k), zeta = -ln e / sqrt(pi^2 + ln^2 e)
// (docs/method.md §1.5, §A8). The force is not clipped to stay repulsive (A8 caveat: clipping
// changes the realised e).
#define BOOST_TEST_MODULE restitution
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"

#include "solid/mass_spring_body.hpp"
#include "solid/spring_dashpot.hpp"
#include "solid/symplectic_euler.hpp"

using namespace ibms;

namespace {

struct Collision {
  double restitution, duration, steps;
  // Through the contact, every 10th step and after separation: time since first touch,
  // normal relative velocity / approach speed (-1 at impact, e after), overlap / contact distance
  // (= diameter).
  std::vector<std::array<double, 3>> history;
};

// Masses 1 and 2 on the x axis, contact distance 1, approach speed 1.5.
Collision collide(double target_restitution) {
  const double stiffness = 1e4, contact_distance = 1.0;
  MassSpringBody pair;
  pair.position = {{0.0, 0.0}, {1.05, 0.0}};
  pair.velocity = {{1.0, 0.0}, {-0.5, 0.0}};
  pair.mass = {1.0, 2.0};
  pair.diameter0 = pair.diameter = 1.0;  // no springs: the contact is the external force
  const double m_eff = 1.0*2.0 / (1.0 + 2.0);
  const double damping = damping_from_restitution(target_restitution, m_eff, stiffness);
  const double t_c = contact_duration(m_eff, stiffness, damping);
  const double dt = t_c / 2000.0;  // >> the 20-50 steps per contact of A8: e within ~1e-3
  const double approach = pair.velocity[0][0] - pair.velocity[1][0];
  bool touched = false;
  double contact_time = 0.0;
  long contact_steps = 0;
  std::vector<std::array<double, 3>> history;
  std::vector<std::array<double, 2>> force(2);
  for (long n = 0; n < 1000000; ++n) {
    const double gap = pair.position[1][0] - pair.position[0][0];
    const double overlap = contact_distance - gap;
    force[0] = force[1] = {0.0, 0.0};
    if (overlap > 0.0) {
      // F on point 0 = -(k delta - c v_n) n, n = +x, v_n = U_1 - U_0 (docs/method.md §1.9).
      const double normal_rate = pair.velocity[1][0] - pair.velocity[0][0];
      const double push = stiffness*overlap - damping*normal_rate;
      force[0][0] = -push;
      force[1][0] = push;
      touched = true;
      if (contact_steps % 10 == 0)
        history.push_back({contact_time, normal_rate / approach, overlap / contact_distance});
      contact_time += dt;
      ++contact_steps;
    } else if (touched) {
      break;
    }
    advance_symplectic_euler(pair, dt, force);
  }
  const double separation = pair.velocity[1][0] - pair.velocity[0][0];
  history.push_back({contact_time, separation / approach,
                     1.0 - (pair.position[1][0] - pair.position[0][0]) / contact_distance});
  return {separation / approach, contact_time, static_cast<double>(contact_steps), history};
}

}  // namespace

BOOST_AUTO_TEST_CASE(rebound_velocity_matches_restitution) {
  BOOST_TEST_MESSAGE("e_target    e_measured    rel. error    t_c measured    t_c (A8)");
  using verification::csv_number;
  const std::string name = "\"two points, linear spring-dashpot\",";
  std::vector<std::string> table, history;
  const double tolerance = 0.01;  // the brief's 1 % target
  for (double e : {0.1, 0.5, 0.9}) {
    const Collision c = collide(e);
    const double m_eff = 2.0/3.0;
    const double t_c = contact_duration(m_eff, 1e4, damping_from_restitution(e, m_eff, 1e4));
    const double error = std::abs(c.restitution - e) / e;
    BOOST_TEST_MESSAGE(e << "    " << c.restitution << "    " << error << "    " << c.duration
                         << "    " << t_c);
    BOOST_TEST(error <= tolerance);
    table.push_back(name + csv_number(e) + "," + csv_number(c.restitution) + "," + csv_number(error) +
                    "," + csv_number(tolerance) + "," + csv_number(c.steps));
    for (const auto& h : c.history)
      history.push_back(name + csv_number(e) + "," + csv_number(h[0] / c.duration) + "," +
                        csv_number(h[1]) + "," + csv_number(h[2]));
  }
  verification::append_results_csv(
      "restitution.csv", "case,e_target,e_measured,rel_error,tolerance,steps_per_contact", table);
  verification::append_results_csv(
      "contact_history.csv",
      "case,e_target,t_over_contact_time,normal_velocity_over_approach,overlap_over_diameter", history);
}

BOOST_AUTO_TEST_CASE(restitution_and_damping_relations_are_inverse) {
  for (double e : {0.05, 0.1, 0.5, 0.9, 1.0}) {
    const double c = damping_from_restitution(e, 0.7, 3e5);
    BOOST_TEST(std::abs(restitution_from_damping(c, 0.7, 3e5) - e) <= 1e-14);  // round-off
  }
  // docs/method.md §1.5: e = 0.5 -> zeta = 0.2155 (4 digits quoted).
  BOOST_TEST(std::abs(damping_ratio_from_restitution(0.5) - 0.2155) <= 5e-5);
}
