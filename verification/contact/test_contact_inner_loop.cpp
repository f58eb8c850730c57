// The contacts' inner loop (contact/contact_subcycle.hpp, multiple time stepping) against the
// shared sub-step (every point of the colliding bodies at the contact sub-step, the scheme of
// ibms before the inner loop), on the head-on collisions of wheel_collision.hpp with no fluid: two
// wheels, and a wheel and a wall, for e_D = 0.1, 0.5, 0.9 and 1 at k_Dn = 1e4 and 1e7.
//  - Stiff wheels (springs 1000 k_Dn, one CDS pair): the springs' sub-step is below the contact's,
//    so the inner loop would take one inner step; the planner keeps the shared sub-step, and the
//    rebound is the shared one exactly (e_D within 1 %, test_wheel_restitution).
//  - Soft wheels (springs k_s = 100: the papers' regime, the contact far stiffer than the body;
//    3-4 inner steps per outer step at 1e4, 74-104 at 1e7 by the group's bound (the table's
//    inner_steps_per_step; the listed pairs' step takes fewer); CDS 0.167 D, the right wheel turned by
//    pi/N_l): the centre-of-mass restitution of the inner loop is within 1 % of the shared
//    sub-step's, and an elastic impact keeps the mechanical energy (point kinetic energies and
//    springs, once the bodies are apart) within 0.5 % in both schemes. The soft wheels'
//    restitution is not e_D: the wheel keeps part of the energy as vibration.
//    Largest overlap, as a mean over three impact phases (initial gaps shifted by 0, 1/3 and 2/3
//    of the travel in one shared sub-step; a single impact's overlap depends on where it falls
//    within a sub-step): for e_D >= 0.9 within 2 % of the shared sub-step's.
//    Not asserted, reported in the table:
//    - the largest overlap of the damped contacts (e_D <= 0.5): the body-mass dashpot stops the
//      first rim point within a few contact sub-steps, so the shared scheme's own value moves by
//      up to 30 % over impact phases and its phase mean lies 2-12 % below its value at a quarter
//      of the sub-step (also reported); the inner loop's phase mean lies 2-17 % below that value;
//    - the soft elastic pair at k_Dn = 1e4, whose rim points rattle: the shared scheme's own
//      centre-of-mass restitution moves by 3.6 % when its sub-step is halved and spans 0.74-0.79
//      over impact phases and sub-steps.
// The outer step as the scene's choice (contact.outer_step_fraction): at half the springs' sub-step
// the damped soft impacts keep the shared sub-step's restitution within 0.25 % and energy within 1 %,
// the elastic wall rebound does not (more than 50 % off).
// With IBMS_RESULTS_DIR set (ctest) the table goes to contact_inner_loop.csv.
// Checks docs/method.md §5.4, §A8: the inner loop's rebound, elastic energy and largest overlap
// against the shared sub-step (§5.4, "The inner step"), and one listed pair taking exactly A8's
// t_c / 20 step count, a damped pair the bound's (more steps).
#define BOOST_TEST_MODULE contact_inner_loop
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"
#include "contact/contact_forces.hpp"
#include "solid/spring_dashpot.hpp"
#include "wheel_collision.hpp"

using namespace ibms;
using namespace ibms::test;

namespace {

const WallBox open_box{{-10.0, -10.0}, {20.0, 20.0}, {false, false}};
const WallBox near_wall_box{{-1.0, -1.0}, {1.9, 2.0}, {false, false}};  // right wall at x = 0.9
constexpr double soft_spring_stiffness = 100.0;  // k_s of the soft wheels [force/length^2]
constexpr double stiff_ratio = 1000.0;           // k_s / k_Dn of the stiff wheels [-]

// One collision: the scheme, and how much finer than the contact sub-step the shared one runs.
struct Setting {
  ContactStepping stepping = ContactStepping::shared;
  double refine = 1.0;       // shared sub-step = contact sub-step / refine
  double gap_offset = 0.0;   // extra initial gap: moves the impact within a sub-step [length]
  double outer_step_fraction = inner_loop_outer_fraction;  // the inner loop's outer step [-]
};

CollisionRecord run_collision(ContactModel model, const WallBox& box, std::vector<MassSpringBody> bodies,
                              const Setting& s) {
  model.steps_per_contact *= s.refine;
  model.outer_step_fraction = s.outer_step_fraction;
  return collide(model, box, bodies, false, s.stepping);
}

CollisionRecord wheel_pair(double e, double k, double spring_k, const Setting& s) {
  const bool stiff = spring_k <= 0.0;
  const double cds = stiff ? 0.05 : 0.167;
  const double half_gap = 0.5 + cds + (stiff ? 0.05 : 0.01) + s.gap_offset;
  const double ratio = stiff ? stiff_ratio : spring_k / k;
  return run_collision(make_contact_model(e, cds, k), open_box,
                       {make_wheel({-half_gap, 0.0}, {0.5*impact_speed, 0.0}, ratio, 0.0, k),
                        make_wheel({half_gap, 0.0}, {-0.5*impact_speed, 0.0}, ratio, stiff ? 0.0 : M_PI / 20.0, k)},
                       s);
}

CollisionRecord wheel_on_wall(double e, double k, double spring_k, const Setting& s) {
  const bool stiff = spring_k <= 0.0;
  const double ratio = stiff ? stiff_ratio : spring_k / k;
  return run_collision(make_contact_model(e, stiff ? 0.05 : 0.167, k), near_wall_box,
                       {make_wheel({(stiff ? 0.3 : 0.2) - s.gap_offset, 0.0}, {impact_speed, 0.0}, ratio, 0.0, k)}, s);
}

using Collision = CollisionRecord (*)(double, double, double, const Setting&);

double energy_change(const CollisionRecord& r) { return (r.energy_after - r.energy_before) / r.energy_before; }

void compare_schemes(const std::string& name, Collision collision, double spring_k) {
  const bool stiff = spring_k <= 0.0;
  BOOST_TEST_MESSAGE(name << ": k_Dn  e_D  e_shared  e_inner  rel_diff  overlap_shared  overlap_inner  rel_diff"
                          "  energy_change_shared  energy_change_inner  inner_steps  seconds_shared  seconds_inner");
  using verification::csv_number;
  std::vector<std::string> rows;
  for (double k : {1e4, 1e7}) {
    for (double e : {0.1, 0.5, 0.9, 1.0}) {
      auto start = std::chrono::steady_clock::now();
      const CollisionRecord shared = collision(e, k, spring_k, {ContactStepping::shared});
      const double seconds_shared = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      start = std::chrono::steady_clock::now();
      const CollisionRecord inner = collision(e, k, spring_k, {ContactStepping::inner_loop});
      const double seconds_inner = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double e_shared = measured_restitution(shared), e_inner = measured_restitution(inner);
      const double e_diff = std::abs(e_inner - e_shared) / e_shared;
      const double overlap_diff = std::abs(inner.max_overlap - shared.max_overlap) / shared.max_overlap;
      const double change_shared = stiff ? centre_energy_change(shared) : energy_change(shared);
      const double change_inner = stiff ? centre_energy_change(inner) : energy_change(inner);
      BOOST_TEST_MESSAGE("  " << k << "  " << e << "  " << e_shared << "  " << e_inner << "  " << e_diff << "  "
                              << shared.max_overlap << "  " << inner.max_overlap << "  " << overlap_diff << "  "
                              << change_shared << "  " << change_inner << "  " << inner.inner_steps << "  "
                              << seconds_shared << "  " << seconds_inner);
      const bool chaotic = !stiff && e == 1.0 && k == 1e4 && collision == &wheel_pair;
      if (!chaotic) BOOST_TEST(e_diff <= 0.01);
      if (stiff) {
        BOOST_TEST(inner.inner_steps == 1);  // the planner's choice: the shared sub-step
        BOOST_TEST(e_inner == e_shared);
        BOOST_TEST(std::abs(e_inner - e) <= 0.01 * e);
      } else {
        BOOST_TEST(inner.inner_steps >= 2);  // the inner loop, not the shared sub-step
      }
      if (e == 1.0) {
        BOOST_TEST(std::abs(change_inner) <= 0.005);
        BOOST_TEST(std::abs(change_shared) <= 0.005);
      }
      double phase_shared = shared.max_overlap, phase_inner = inner.max_overlap, phase_fine = 0.0;
      if (stiff) {
        BOOST_TEST(overlap_diff <= 0.02);
      } else {
        // Means over three impact phases (initial gaps 0, 1/3 and 2/3 of the travel in a
        // sub-step, v0 dt_c) against the shared scheme at a quarter of its sub-step.
        const double travel = impact_speed * shared.substep;
        for (int phase = 0; phase < 3; ++phase) {
          const double offset = travel * phase / 3.0;
          if (phase > 0) {
            phase_shared += collision(e, k, spring_k, {ContactStepping::shared, 1.0, offset}).max_overlap;
            phase_inner += collision(e, k, spring_k, {ContactStepping::inner_loop, 1.0, offset}).max_overlap;
          }
          phase_fine += collision(e, k, spring_k, {ContactStepping::shared, 4.0, offset}).max_overlap;
        }
        phase_shared /= 3.0;
        phase_inner /= 3.0;
        phase_fine /= 3.0;
        BOOST_TEST_MESSAGE("    mean largest overlap over three impact phases: shared " << phase_shared << ", inner "
                           << phase_inner << ", shared at a quarter sub-step " << phase_fine);
        if (e >= 0.9) BOOST_TEST(std::abs(phase_inner - phase_shared) <= 0.02 * phase_shared);
      }
      rows.push_back("\"" + name + "\"," + csv_number(k) + "," + csv_number(e) + "," + csv_number(e_shared) + "," +
                     csv_number(e_inner) + "," + csv_number(shared.max_overlap) + "," + csv_number(inner.max_overlap) +
                     "," + csv_number(phase_shared) + "," + csv_number(phase_inner) + "," + csv_number(phase_fine) +
                     "," + csv_number(change_shared) + "," + csv_number(change_inner) + "," +
                     csv_number(inner.inner_steps) + "," + csv_number(seconds_shared) + "," +
                     csv_number(seconds_inner));
    }
  }
  verification::append_results_csv("contact_inner_loop.csv",
                                    "case,k_dn,e_d,e_shared,e_inner,max_overlap_shared,max_overlap_inner,"
                                    "phase_mean_overlap_shared,phase_mean_overlap_inner,phase_mean_overlap_quarter_step,"
                                    "energy_change_shared,energy_change_inner,inner_steps_per_step,seconds_shared,"
                                    "seconds_inner",
                                    rows);
}

}  // namespace

BOOST_AUTO_TEST_CASE(stiff_wheel_pair_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wheel, stiff", wheel_pair, 0.0);
}

BOOST_AUTO_TEST_CASE(stiff_wheel_on_wall_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wall, stiff", wheel_on_wall, 0.0);
}

BOOST_AUTO_TEST_CASE(soft_wheel_pair_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wheel, soft", wheel_pair, soft_spring_stiffness);
}

BOOST_AUTO_TEST_CASE(soft_wheel_on_wall_inner_loop_matches_shared_substep) {
  compare_schemes("wheel-wall, soft", wheel_on_wall, soft_spring_stiffness);
}

// The outer step as a scene's choice (contact.outer_step_fraction, ContactModel::outer_step_fraction):
// at half the springs' stable sub-step instead of the default sixteenth, damped contacts (e_D <= 0.8,
// the dashpot from the bodies' effective mass) keep the shared sub-step's centre-of-mass restitution
// within 0.25 % and the mechanical energy after the impact within 1 % of the kinetic energy
// (measured: 0.14 % and 0.74 % at worst, e_D = 0.8 against the wall); elastic contacts do not,
// which is why the default stays a sixteenth: the soft wheel's rebound from the wall at k_Dn = 1e7
// is more than 50 % off at a half (0.270 against 0.128), 0.9 % at the default.
BOOST_AUTO_TEST_CASE(a_coarser_outer_step_keeps_damped_impacts_not_elastic_ones) {
  const Setting shared{ContactStepping::shared};
  const Setting inner{ContactStepping::inner_loop};
  const Setting half{ContactStepping::inner_loop, 1.0, 0.0, 0.5};
  for (Collision collision : {&wheel_pair, &wheel_on_wall})
    for (double k : {1e4, 1e7})
      for (double e : {0.1, 0.5, 0.8}) {
        const CollisionRecord reference = collision(e, k, soft_spring_stiffness, shared);
        const CollisionRecord coarse = collision(e, k, soft_spring_stiffness, half);
        const double e_diff = std::abs(measured_restitution(coarse) / measured_restitution(reference) - 1.0);
        const double energy_diff = std::abs(energy_change(coarse) - energy_change(reference));
        BOOST_TEST_MESSAGE((collision == &wheel_pair ? "pair" : "wall") << " k_Dn " << k << " e_D " << e
                           << ": outer step 1/2, restitution off by " << e_diff << ", energy by " << energy_diff
                           << " (" << coarse.inner_steps << " inner steps per outer step)");
        BOOST_TEST(coarse.inner_steps > 1);  // the inner loop, at the coarser outer step
        BOOST_TEST(e_diff <= 0.0025);
        BOOST_TEST(energy_diff <= 0.01);
      }
  // Elastic, against the wall at k_Dn = 1e7: the default resolves the rebound, half the sub-step not.
  const double k = 1e7;
  const double e_shared = measured_restitution(wheel_on_wall(1.0, k, soft_spring_stiffness, shared));
  const double e_default = measured_restitution(wheel_on_wall(1.0, k, soft_spring_stiffness, inner));
  const double e_half = measured_restitution(wheel_on_wall(1.0, k, soft_spring_stiffness, half));
  BOOST_TEST_MESSAGE("elastic wall impact, k_Dn 1e7: restitution shared " << e_shared << ", default outer step "
                     << e_default << ", half the springs' sub-step " << e_half);
  BOOST_TEST(std::abs(e_default / e_shared - 1.0) <= 0.01);
  BOOST_TEST(std::abs(e_half / e_shared - 1.0) > 0.5);
}

// The inner step of contact.inner_step = "listed_pairs" (contact_subcycle.hpp): with a single CDS
// pair in the list it is A8's bound exactly, t_c / steps_per_contact with t_c = pi sqrt(m_eff / k_Dn)
// of the two rim points; "lightest_point" takes the group's bound, which assumes that point in four
// pairs at once (twice as many inner steps). Two soft wheels at rest, rim points facing on the x
// axis with CDS 1e-4 apart: the neighbouring rim points lie 0.09 beyond the skin, so the list holds
// one pair.
BOOST_AUTO_TEST_CASE(listed_pairs_inner_step_is_the_single_pair_contact_duration) {
  const double k = 1e7, cds = 0.05, gap = 1e-4, dt_outer = 1e-3;
  const double c = 0.5 + cds + 0.5 * gap;
  const std::vector<MassSpringBody> start{make_wheel({-c, 0.0}, {0.0, 0.0}, soft_spring_stiffness / k, 0.0, k),
                                          make_wheel({c, 0.0}, {0.0, 0.0}, soft_spring_stiffness / k, M_PI, k)};
  const std::vector<std::vector<std::array<double, 2>>> no_external{
      std::vector<std::array<double, 2>>(start[0].n_points(), {0.0, 0.0}),
      std::vector<std::array<double, 2>>(start[1].n_points(), {0.0, 0.0})};
  const double m_eff = 0.5 * start[0].mass[0];  // two equal rim points
  const double duration = M_PI * std::sqrt(m_eff / k);
  ContactModel model = make_contact_model(1.0, cds, k);
  const int n_group = static_cast<int>(std::ceil(dt_outer / contact_substep(model, start) * (1.0 - 1e-12)));
  ContactSubcycler subcycler;
  std::vector<MassSpringBody> bodies = start;
  const ContactSubcycleResult listed =
      advance_bodies_inner_loop(model, open_box, dt_outer, n_group, no_external, bodies, subcycler, false);
  const int expected = static_cast<int>(std::ceil(dt_outer / (duration / model.steps_per_contact) * (1.0 - 1e-12)));
  BOOST_TEST_MESSAGE("single listed pair: " << listed.inner_steps << " inner steps (t_c / 20: " << expected
                                            << "), group bound " << n_group);
  BOOST_TEST(listed.list_builds == 1);
  BOOST_TEST(listed.inner_steps == expected);
  model.inner_step = InnerStepBound::lightest_point;
  bodies = start;
  ContactSubcycler fixed;
  const ContactSubcycleResult lightest =
      advance_bodies_inner_loop(model, open_box, dt_outer, n_group, no_external, bodies, fixed, false);
  BOOST_TEST(lightest.inner_steps == n_group);
  BOOST_TEST(std::abs(n_group - 2 * expected) <= 1);

  // Damped (e_D = 0.5, the dashpot from the bodies' effective mass): the pair's rate bound is
  // sqrt(k / m_eff) + c / m_eff (the two 2x2 systems' radii, exact for one pair), and the step is
  // also kept below the group's dashpot limit.
  ContactModel damped = make_contact_model(0.5, cds, k);
  const double dashpot =
      2.0 * damping_ratio_from_restitution(0.5) * std::sqrt(contact_effective_mass(damped, start, 0, 0, 1, 0) * k);
  const double rate = std::sqrt(k / m_eff) + dashpot / m_eff;
  const double limit = std::min(M_PI / (damped.steps_per_contact * rate), contact_dashpot_substep(damped, start));
  const int expected_damped = static_cast<int>(std::ceil(dt_outer / limit * (1.0 - 1e-12)));
  bodies = start;
  ContactSubcycler damped_loop;
  const ContactSubcycleResult damped_result =
      advance_bodies_inner_loop(damped, open_box, dt_outer, n_group, no_external, bodies, damped_loop, false);
  BOOST_TEST_MESSAGE("single damped listed pair: " << damped_result.inner_steps << " inner steps (bound: "
                                                   << expected_damped << ")");
  BOOST_TEST(damped_result.list_builds == 1);
  BOOST_TEST(damped_result.inner_steps == expected_damped);
  BOOST_TEST(expected_damped > expected);  // the dashpot shortens the step
}
