// The numbers of docs/method.md §5.2 ("Numbers for the papers' cases") for the wheels the shipped
// scenes build (read with the scene reader, built by Simulation as a run builds them), from the
// exact eigenvalues of M^-1 K and M^-1 C at rest (Eigen; the table was made by power iteration).
// Each figure is asserted within the rounding of its printed digits (4.1e5: [4.05e5, 4.15e5]).
// Claims asserted:
//  1. The table's rows: the papers' settling disk (k_s = 4e6, e_s = 0.5, N_l = 70: the
//     swelling-sedimentation scene at D0) N = 71, M = 8.64e-4, c = 17.9, omega_max = 4.1e5,
//     2/omega_max = 4.9e-6 s, damping limit 2/lambda_max(M^-1 C) = 2.7e-6 s; the one-sided cavity
//     k = 10 and k = 100, c = 100 (every body of each scene): N = 22, M = 2.14, omega_max = 7.3 and
//     23, 2/omega_max = 0.27 and 0.086, damping limit 3.7e-3. The settling-disk benchmark scene
//     (N_l = 80), named below the table: omega_max 4.65e5, 2/omega_max 4.30e-6 s, damping limit
//     2.20e-6 s.
//  2. The stiffest mode is the hub, omega ~ sqrt((N_l/2) k / M): the centre point carries most
//     (> 1/2) of that mode's kinetic energy (measured 0.97 for N_l = 70 and 80, 0.91 for N_l = 21),
//     and omega_max is within 5 % of the estimate (measured +1.4 % for N_l = 70, +1.2 % for
//     N_l = 80, +4.7 % for N_l = 21: the rim's recoil and the ring springs stiffen it).
//  3. For the settling disk the explicit bound (springs and dashpots together,
//     4 / (gamma + sqrt(gamma^2 + 4 omega^2)), §5.1) is about 2e-6 s (measured 2.16e-6 s; 1.81e-6 s
//     for N_l = 80), the run's fluid steps lie in 1e-4 - 1e-3 s, explicit springs would need hundreds
//     of sub-steps at the run's step (measured 941 at its first step, 1e-3 s; 280 for the benchmark
//     scene at 2.5e-4 s), and spring_stepping under "auto" takes the implicit step there (at 1e-4,
//     the run's step and 1e-3).
//  4. The cavity cases are damping-limited at a few ms (the damping limit, 3.7e-3, below
//     2/omega_max and in [1, 10) ms), and at their fluid step 0.02 (run.max_time_step, the step
//     the run takes) spring_stepping keeps the explicit step with sub-steps of 1.7 ms, half the
//     limit's Gershgorin bound of 3.5 ms: 12 per fluid step (method.md said "one or two" before
//     this test; the scenes' step has been 0.02 since they were added).
#define BOOST_TEST_MODULE wheel_numbers
#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "scene/scene_reader.hpp"
#include "sim/bodies/body_update.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step_limits.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/stable_substep.hpp"

using namespace ibms;

namespace {

// Exact spectra of the wheel at rest: M^-1 K and M^-1 C have the eigenvalues of M^-1/2 K M^-1/2 and
// M^-1/2 C M^-1/2 (symmetric), K = sum k e e^T and C = sum c e e^T over the springs' 2x2 blocks.
struct Spectrum {
  double omega_max = 0.0;     // sqrt(lambda_max(M^-1 K)) [1/time]
  double damping_max = 0.0;   // lambda_max(M^-1 C) [1/time]
  double centre_share = 0.0;  // share of the stiffest mode's kinetic energy on the centre point [-]
};

Spectrum exact_spectrum(const MassSpringBody& body) {
  const int n = body.n_points();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2*n, 2*n), C = Eigen::MatrixXd::Zero(2*n, 2*n);
  const auto add = [](Eigen::MatrixXd& A, const Spring& s, const Eigen::Matrix2d& b) {
    A.block<2, 2>(2*s.i, 2*s.i) += b;  A.block<2, 2>(2*s.j, 2*s.j) += b;
    A.block<2, 2>(2*s.i, 2*s.j) -= b;  A.block<2, 2>(2*s.j, 2*s.i) -= b;
  };
  for (const Spring& s : body.springs) {
    Eigen::Vector2d e(body.position[s.j][0] - body.position[s.i][0], body.position[s.j][1] - body.position[s.i][1]);
    e.normalize();
    const Eigen::Matrix2d ee = e * e.transpose();
    add(K, s, s.stiffness * ee);
    add(C, s, s.damping * ee);
  }
  for (int r = 0; r < 2*n; ++r)
    for (int c = 0; c < 2*n; ++c) {
      const double w = std::sqrt(body.mass[r/2] * body.mass[c/2]);
      K(r, c) /= w;
      C(r, c) /= w;
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> stiffness(K);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> damping(C, Eigen::EigenvaluesOnly);
  Spectrum out;
  out.omega_max = std::sqrt(stiffness.eigenvalues()(2*n - 1));
  out.damping_max = damping.eigenvalues()(2*n - 1);
  // The eigenvector is in M^1/2 x coordinates: |v_i|^2 is point i's share of the mode's kinetic energy.
  const Eigen::VectorXd v = stiffness.eigenvectors().col(2*n - 1);
  const int c = body.centre_index();
  out.centre_share = (v(2*c)*v(2*c) + v(2*c + 1)*v(2*c + 1)) / v.squaredNorm();
  return out;
}

// Springs and dashpots together, §5.1: the stable symplectic-Euler step of the stiffest mode. The
// wheels here have uniform c/k (equal masses), so C = (c/k) K and omega_max, gamma_max are one mode's.
double combined_limit(const Spectrum& s) {
  const double g = s.damping_max, w = s.omega_max;
  return 4.0 / (g + std::sqrt(g*g + 4.0*w*w));
}

// value within the rounding of a figure printed as `printed` (half_unit: half its last digit).
void check_printed(const char* what, double value, double printed, double half_unit, bool message = true) {
  if (message) BOOST_TEST_MESSAGE("  " << what << " = " << value << " (method.md: " << printed << ")");
  BOOST_TEST(std::abs(value - printed) <= half_unit, what << " = " << value << " is not " << printed
                                                          << " to its printed digits (+-" << half_unit << ")");
}

Simulation simulation_of(const char* path) { return Simulation(read_scene_file(path)); }

struct Row {
  const char* name;
  const char* scene;
  int n_points;
  double mass, mass_half_unit;
  double damping, damping_half_unit;  // c of every spring
  double omega, omega_half_unit;
  double period, period_half_unit;    // 2 / omega_max
  double limit, limit_half_unit;      // 2 / lambda_max(M^-1 C)
};

void check_row(const Row& row) {
  BOOST_TEST_MESSAGE(row.name << " (" << row.scene << ")");
  const Simulation sim = simulation_of(row.scene);
  BOOST_TEST_REQUIRE(!sim.bodies().empty());
  for (const MassSpringBody& body : sim.bodies()) {
    const bool first = &body == &sim.bodies().front();
    BOOST_TEST(body.n_points() == row.n_points);
    for (const double m : body.mass) BOOST_TEST(std::abs(m - row.mass) <= row.mass_half_unit);
    for (const Spring& s : body.springs) BOOST_TEST(std::abs(s.damping - row.damping) <= row.damping_half_unit);
    const Spectrum s = exact_spectrum(body);
    check_printed("M", body.mass[0], row.mass, row.mass_half_unit, first);
    check_printed("c", body.springs[0].damping, row.damping, row.damping_half_unit, first);
    check_printed("omega_max", s.omega_max, row.omega, row.omega_half_unit, first);
    check_printed("2/omega_max", 2.0 / s.omega_max, row.period, row.period_half_unit, first);
    check_printed("2/lambda_max(M^-1 C)", 2.0 / s.damping_max, row.limit, row.limit_half_unit, first);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_tables_rows_are_the_shipped_wheels) {
  check_row({"settling disk (the papers' N_l = 70, swelling sedimentation at D0)", IBMS_SWELLING_SEDIMENTATION_SCENE,
             71, 8.64e-4, 0.005e-4, 17.9, 0.05, 4.1e5, 0.05e5, 4.9e-6, 0.05e-6, 2.7e-6, 0.05e-6});
  check_row({"one-sided cavity k = 10", IBMS_CAVITY_K10_SCENE,
             22, 2.14, 0.005, 100.0, 0.0, 7.3, 0.05, 0.27, 0.005, 3.7e-3, 0.05e-3});
  check_row({"one-sided cavity k = 100", IBMS_CAVITY_K100_SCENE,
             22, 2.14, 0.005, 100.0, 0.0, 23.0, 0.5, 0.086, 0.0005, 3.7e-3, 0.05e-3});
  // The settling-disk benchmark scene (N_l = 80), given below the table with three digits.
  BOOST_TEST_MESSAGE("settling-disk benchmark (" << IBMS_SETTLING_SCENE << ")");
  const Simulation sim = simulation_of(IBMS_SETTLING_SCENE);
  const MassSpringBody& body = sim.bodies().at(0);
  BOOST_TEST(body.n_surface == 80);
  const Spectrum s = exact_spectrum(body);
  check_printed("omega_max", s.omega_max, 4.65e5, 0.005e5);
  check_printed("2/omega_max", 2.0 / s.omega_max, 4.30e-6, 0.005e-6);
  check_printed("2/lambda_max(M^-1 C)", 2.0 / s.damping_max, 2.20e-6, 0.005e-6);
}

BOOST_AUTO_TEST_CASE(the_stiffest_mode_is_the_hub) {
  for (const char* scene : {IBMS_SWELLING_SEDIMENTATION_SCENE, IBMS_SETTLING_SCENE, IBMS_CAVITY_K10_SCENE,
                            IBMS_CAVITY_K100_SCENE}) {
    const Simulation sim = simulation_of(scene);
    const MassSpringBody& body = sim.bodies().at(0);
    const double k = body.springs.at(0).stiffness, M = body.mass.at(0);
    const double hub = std::sqrt(0.5 * body.n_surface * k / M);
    const Spectrum s = exact_spectrum(body);
    BOOST_TEST_MESSAGE(scene << ": N_l = " << body.n_surface << ", omega_max / sqrt((N_l/2) k/M) = "
                             << s.omega_max / hub << ", centre's share of the mode's energy " << s.centre_share);
    BOOST_TEST(std::abs(s.omega_max / hub - 1.0) <= 0.05);
    BOOST_TEST(s.centre_share > 0.5);
  }
}

BOOST_AUTO_TEST_CASE(auto_takes_the_implicit_step_for_the_settling_disk) {
  for (const char* scene : {IBMS_SWELLING_SEDIMENTATION_SCENE, IBMS_SETTLING_SCENE}) {
    const Simulation sim = simulation_of(scene);
    const MassSpringBody& body = sim.bodies().at(0);
    BOOST_TEST_REQUIRE((body.integrator == SpringIntegrator::automatic));
    const double bound = combined_limit(exact_spectrum(body));
    const double dt = planned_time_step(sim);
    const int explicit_substeps = static_cast<int>(std::ceil(dt / stable_substep(body)));
    SpectralWorkspace scratch;
    BOOST_TEST_MESSAGE(scene << ": explicit bound " << bound << " s, the run's step " << dt << " s, "
                             << explicit_substeps << " explicit sub-steps (safety 0.5) at it");
    check_printed("explicit bound (springs + dashpots)", bound, 2e-6, 0.5e-6);
    BOOST_TEST(dt >= 1e-4);
    BOOST_TEST(dt <= 1e-3);
    BOOST_TEST(explicit_substeps >= 100);  // hundreds
    BOOST_TEST(explicit_substeps < 1000);
    for (const double step : {1e-4, dt, 1e-3}) {
      const SpringStepping stepping = spring_stepping(body, step, scratch);
      BOOST_TEST(stepping.implicit, "dt = " << step << ": explicit sub-step " << stepping.substep);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_cavities_are_damping_limited_and_sub_stepped_explicitly) {
  for (const char* scene : {IBMS_CAVITY_K10_SCENE, IBMS_CAVITY_K100_SCENE}) {
    const Simulation sim = simulation_of(scene);
    const double dt = planned_time_step(sim);
    BOOST_TEST(dt == 0.02);  // run.max_time_step: CFL 0.4 at the lid's 0.1 allows 0.04
    SpectralWorkspace scratch;
    for (const MassSpringBody& body : sim.bodies()) {
      const Spectrum s = exact_spectrum(body);
      const double damping_limit = 2.0 / s.damping_max;
      BOOST_TEST(damping_limit < 2.0 / s.omega_max);
      BOOST_TEST(damping_limit >= 1e-3);  // a few ms
      BOOST_TEST(damping_limit < 1e-2);
      const SpringStepping stepping = spring_stepping(body, dt, scratch);
      BOOST_TEST(!stepping.implicit);
      const int substeps = static_cast<int>(std::ceil(dt / stepping.substep));
      const bool first = &body == &sim.bodies().front();
      if (first) BOOST_TEST_MESSAGE(scene << ": damping limit " << damping_limit << ", 2/omega_max " << 2.0 / s.omega_max
                               << ", sub-step " << stepping.substep << ", " << substeps << " per fluid step of " << dt);
      check_printed("explicit sub-step", stepping.substep, 1.7e-3, 0.05e-3, first);
      // the sub-step is half the combined limit as the Gershgorin bounds of §5.1 give it (exact: 3.72 ms)
      check_printed("bound on the explicit limit", 2.0 * stepping.substep, 3.5e-3, 0.05e-3, first);
      BOOST_TEST(substeps == 12);
    }
  }
}
