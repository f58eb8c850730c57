// The contacts' inner loop (contact/contact_subcycle.hpp, multiple time stepping) against the
// shared sub-step (every point of the colliding bodies at the contact sub-step), on the head-on
// collisions of wheel_collision.hpp with no fluid: two wheels, and a wheel and a wall.
//  - With one inner step per outer step (stiff wheels: the springs' sub-step is below the
//    contact's) the inner loop is the shared sub-step: the same rebound to round-off.
//  - Soft wheels (springs k_s = 100 against k_Dn = 1e4 and 1e7, the papers' regime: the contact
//    far stiffer than the body, hundreds of inner steps per outer step): for e_D = 0.1, 0.5, 0.9
//    and 1 the centre-of-mass restitution of the inner loop is within 1 % of the shared
//    sub-step's, its largest overlap within 2 %, and an elastic collision (e_D = 1) keeps the
//    mechanical energy (point kinetic energies + springs, measured once the bodies are apart)
//    within 0.5 %.
// The soft wheels' restitution is not e_D: the wheel deforms and keeps part of the energy as
// vibration; what is compared is the two schemes on the same law.
// With IBMS_RESULTS_DIR set (ctest) the table goes to contact_inner_loop.csv.
#define BOOST_TEST_MODULE contact_inner_loop
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

const WallBox open_box{{-10.0, -10.0}, {20.0, 20.0}, {false, false}};
const WallBox near_wall_box{{-1.0, -1.0}, {1.9, 2.0}, {false, false}};  // right wall at x = 0.9
constexpr double soft_spring_stiffness = 100.0;  // k_s of the soft wheels [force/length^2]

struct Run {
  CollisionRecord record;
  double seconds = 0.0;
};

Run wheel_pair(double restitution, double contact_k, double spring_k, ContactStepping stepping) {
  const double cds_fraction = 0.167;  // the two-sided cavity's CDS radius
  const double half_gap = 0.5 + cds_fraction + 0.01;
  const double ratio = spring_k / contact_k;
  const auto start = std::chrono::steady_clock::now();
  Run run;
  run.record = collide(make_contact_model(restitution, cds_fraction, contact_k), open_box,
                       {make_wheel({-half_gap, 0.0}, {0.5*impact_speed, 0.0}, ratio, 0.0, contact_k),
                        make_wheel({half_gap, 0.0}, {-0.5*impact_speed, 0.0}, ratio, M_PI / 20.0, contact_k)},
                       /*implicit_springs=*/false, stepping);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

Run wheel_on_wall(double restitution, double contact_k, double spring_k, ContactStepping stepping) {
  const auto start = std::chrono::steady_clock::now();
  Run run;
  run.record = collide(make_contact_model(restitution, 0.167, contact_k), near_wall_box,
                       {make_wheel({0.2, 0.0}, {impact_speed, 0.0}, spring_k / contact_k, 0.0, contact_k)},
                       /*implicit_springs=*/false, stepping);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

using Collision = Run (*)(double, double, double, ContactStepping);

void compare_schemes(const std::string& name, Collision collision) {
  BOOST_TEST_MESSAGE(name << ": k_Dn  e_D  e_shared  e_inner  rel_diff  overlap_shared  overlap_inner  rel_diff"
                          "  energy_change_shared  energy_change_inner  inner_steps  time_shared  time_inner");
  using verification::csv_number;
  std::vector<std::string> rows;
  for (double k : {1e4, 1e7}) {
    for (double e : {0.1, 0.5, 0.9, 1.0}) {
      const Run shared = collision(e, k, soft_spring_stiffness, ContactStepping::shared);
      const Run inner = collision(e, k, soft_spring_stiffness, ContactStepping::inner_loop);
      const double e_shared = measured_restitution(shared.record), e_inner = measured_restitution(inner.record);
      const double e_diff = std::abs(e_inner - e_shared) / e_shared;
      const double overlap_diff =
          std::abs(inner.record.max_overlap - shared.record.max_overlap) / shared.record.max_overlap;
      const auto energy_change = [](const CollisionRecord& r) {
        return (r.energy_after - r.energy_before) / r.energy_before;
      };
      BOOST_TEST_MESSAGE("  " << k << "  " << e << "  " << e_shared << "  " << e_inner << "  " << e_diff << "  "
                              << shared.record.max_overlap << "  " << inner.record.max_overlap << "  " << overlap_diff
                              << "  " << energy_change(shared.record) << "  " << energy_change(inner.record) << "  "
                              << inner.record.inner_steps << "  " << shared.seconds << "  " << inner.seconds);
      BOOST_TEST(inner.record.inner_steps >= 10);  // the test is about many inner steps per outer step
      BOOST_TEST(e_diff <= 0.01);
      BOOST_TEST(overlap_diff <= 0.02);
      if (e == 1.0) {
        BOOST_TEST(std::abs(energy_change(inner.record)) <= 0.005);
        BOOST_TEST(std::abs(energy_change(shared.record)) <= 0.005);
      }
      rows.push_back("\"" + name + "\"," + csv_number(k) + "," + csv_number(e) + "," + csv_number(e_shared) + "," +
                     csv_number(e_inner) + "," + csv_number(shared.record.max_overlap) + "," +
                     csv_number(inner.record.max_overlap) + "," + csv_number(energy_change(shared.record)) + "," +
                     csv_number(energy_change(inner.record)) + "," + csv_number(inner.record.inner_steps));
    }
  }
  verification::append_results_csv("contact_inner_loop.csv",
                                    "case,k_dn,e_d,e_shared,e_inner,max_overlap_shared,max_overlap_inner,"
                                    "energy_change_shared,energy_change_inner,inner_steps_per_step",
                                    rows);
}

}  // namespace

BOOST_AUTO_TEST_CASE(one_inner_step_is_the_shared_substep) {
  // Stiff wheels (springs 1000 k_Dn): the springs' sub-step is below the contact's, one inner step.
  const double half_gap = 0.5 + 0.05 + 0.05;
  const std::vector<MassSpringBody> wheels = {make_wheel({-half_gap, 0.0}, {0.5, 0.0}, 1000.0),
                                              make_wheel({half_gap, 0.0}, {-0.5, 0.0}, 1000.0)};
  for (double e : {0.1, 1.0}) {
    const CollisionRecord shared = collide(make_contact_model(e), open_box, wheels);
    const CollisionRecord inner =
        collide(make_contact_model(e), open_box, wheels, false, ContactStepping::inner_loop);
    BOOST_TEST(inner.inner_steps == 1);
    BOOST_TEST(inner.substep == shared.substep);
    BOOST_TEST(std::abs(measured_restitution(inner) - measured_restitution(shared)) <= 1e-9);
    BOOST_TEST(std::abs(inner.max_overlap - shared.max_overlap) <= 1e-9 * shared.max_overlap);
  }
}

BOOST_AUTO_TEST_CASE(soft_wheel_pair_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wheel, soft", wheel_pair);
}

BOOST_AUTO_TEST_CASE(soft_wheel_on_wall_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wall, soft", wheel_on_wall);
}
