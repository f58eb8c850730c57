// stable_substep (docs/method.md §5.1, §5.3) is meaningful: a wheel integrated at the returned
// sub-step (safety 0.5) stays bounded, and at 3x that step it blows up. The bound on omega_max
// is compared with the exact largest eigenvalue of M^-1 K (Eigen): above it, by at most 7 %.
#define BOOST_TEST_MODULE stable_substep
#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "solid/mass_spring_body.hpp"
#include "solid/spring_forces.hpp"
#include "solid/stable_substep.hpp"
#include "solid/symplectic_euler.hpp"

using namespace ibms;

namespace {

MassSpringBody perturbed_wheel(double restitution, bool cross) {
  BodyParameters spec;
  spec.diameter = 1.0;
  spec.n_surface_points = 20;
  spec.density = 1.0;
  spec.spring_stiffness = 1e3;
  spec.spring_damping = restitution < 1.0 ? -1.0 : 0.0;
  spec.restitution_coefficient = restitution;
  spec.cross_springs = cross;
  MassSpringBody body = build_wheel(spec);
  // Random 1 % displacements excite every mode, the stiffest (hub) one included.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-0.01, 0.01);
  for (auto& x : body.position) { x[0] += uniform(rng); x[1] += uniform(rng); }
  return body;
}

double total_energy(const MassSpringBody& body) {
  return kinetic_energy(body) + spring_energy(body, body.length_scale());
}

// Largest E/E0 over n_steps (infinity once non-finite).
double max_energy_ratio(MassSpringBody body, double dt, long n_steps) {
  const double e0 = total_energy(body);
  const std::vector<std::array<double, 2>> no_force(body.n_points(), {0.0, 0.0});
  double worst = 1.0;
  for (long n = 0; n < n_steps; ++n) {
    advance_symplectic_euler(body, dt, no_force);
    const double ratio = total_energy(body) / e0;
    if (!std::isfinite(ratio) || ratio > 1e12) return INFINITY;
    worst = std::max(worst, ratio);
  }
  return worst;
}

// Exact omega_max^2 at rest: largest eigenvalue of M^-1/2 K M^-1/2 with K = sum k e e^T blocks.
double exact_omega_squared(const MassSpringBody& body) {
  const int n = body.n_points();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2*n, 2*n);
  for (const Spring& s : body.springs) {
    Eigen::Vector2d e(body.position[s.j][0] - body.position[s.i][0],
                      body.position[s.j][1] - body.position[s.i][1]);
    e.normalize();
    const Eigen::Matrix2d b = s.stiffness * e * e.transpose();
    K.block<2, 2>(2*s.i, 2*s.i) += b;  K.block<2, 2>(2*s.j, 2*s.j) += b;
    K.block<2, 2>(2*s.i, 2*s.j) -= b;  K.block<2, 2>(2*s.j, 2*s.i) -= b;
  }
  for (int r = 0; r < 2*n; ++r)
    for (int c = 0; c < 2*n; ++c) K(r, c) /= std::sqrt(body.mass[r/2] * body.mass[c/2]);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().maxCoeff();
}

constexpr long n_steps = 20000;  // ~2000 periods of the stiffest mode

}  // namespace

BOOST_AUTO_TEST_CASE(run_at_stable_substep_stays_bounded) {
  BOOST_TEST_MESSAGE("case    omega bound/exact(at rest)    dt    max E/E0");
  for (double e : {1.0, 0.5})
    for (bool cross : {false, true}) {
      const MassSpringBody body = perturbed_wheel(e, cross);
      const double ratio = std::sqrt(spectral_bounds(body).omega_squared_max / exact_omega_squared(body));
      const double dt = stable_substep(body);
      const double worst = max_energy_ratio(body, dt, n_steps);
      BOOST_TEST_MESSAGE("e=" << e << (cross ? " cross" : "") << "    " << ratio << "    " << dt << "    " << worst);
      BOOST_TEST(ratio >= 1.0);  // a bound, never an underestimate
      // and a tight one (measured 1.036 and 1.059: the Collatz-Wielandt iteration, stopped once an
      // iterate gains less than 1e-4, approaches rho(|M^-1 K|)); a looser one wastes sub-steps
      BOOST_TEST(ratio <= 1.07);
      // omega dt <= 1 at safety 0.5, and symplectic Euler keeps H~ = H - (dt/2) omega^2 x v, so
      // H <= H0 (1 + omega dt/2)/(1 - omega dt/2) <= 3 H0 (damping only lowers it).
      BOOST_TEST(worst <= 3.0);
    }
}

BOOST_AUTO_TEST_CASE(run_at_three_times_the_stable_substep_blows_up) {
  BOOST_TEST_MESSAGE("case    3 dt    max E/E0");
  for (double e : {1.0, 0.5})
    for (bool cross : {false, true}) {
      const MassSpringBody body = perturbed_wheel(e, cross);
      const double dt = 3.0 * stable_substep(body);
      const double worst = max_energy_ratio(body, dt, n_steps);
      BOOST_TEST_MESSAGE("e=" << e << (cross ? " cross" : "") << "    " << dt << "    " << worst);
      // 3 x 0.5 = 1.5x the bound, and the bound is within ~6 % of the true limit for the wheel,
      // so the stiffest mode grows by a factor > 1 every step: the energy leaves 1e12 E0.
      BOOST_TEST(std::isinf(worst));
    }
}
