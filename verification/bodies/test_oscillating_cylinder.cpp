// A moving body against an exact solution: a prescribed cylinder oscillating with small amplitude
// in fluid at rest, under the end-of-step coupling (ibm.coupling = "no_slip", faces), against the
// unsteady Stokes flow (Stokes 1851; oscillating_cylinder.hpp). The in-line force of the last of
// three periods is fitted as F = -C_m m_f dU/dt - C_d m_f U; both parts are compared with the exact
// ones over D/h = 10, 20, 40 with the step refined with h (50, 100, 200 steps a period).
//  - Markers retracted by 0.3 h: the face constraint's body acts 0.285 h larger than its rim
//    (docs/method.md §3.7, "Effective radius"); the added mass grows with the square of the radius.
//  - The box (8 D, walls) adds the confinement of a dipole, ~ (D/L)^2: measured at D/h = 20 as
//    (4/3) (F(8 D) - F(16 D)) (the 1/L^2 law checked at D/h = 10 with 8, 16 and 32 D: the
//    differences fall by 4.1 and 4.4) and removed from every grid; the test prints it.
// Claims: each part's error falls at an order in [1, 3] between successive grids, and both are
// within 1 % of the exact values on the finest grid; the marker system takes at most 2 products a
// step on every grid.
#define BOOST_TEST_MODULE oscillating_cylinder
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gsl/gsl_sf_bessel.h>

#include "../common/convergence.hpp"
#include "core/constants.hpp"
#include "oscillating_cylinder.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

using namespace ibms;

namespace {

// Cylinder D = 1 (a = 1/2), X_c(t) = X0 - A cos(w t) (at rest at t = 0), T = 1, A = D / 200
// (Keulegan-Carpenter number 2 pi A / D = 0.031: the convective terms change the first harmonic by
// O(KC^2)), nu = w a^2 / 25 so that |s| = a sqrt(w / nu) = 5: the Stokes layer sqrt(2 nu / w) is
// 0.14 D, both force parts of order one.
constexpr double diameter = 1.0, period = 1.0, amplitude = 0.005;
constexpr double omega = 2.0 * pi / period;
constexpr double nu = omega * 0.25 / 25.0;
constexpr int periods = 3;
constexpr double retraction = 0.3;  // ibm.marker_retraction [h]

struct Fit {
  double added_mass = 0.0;  // C_m [-]
  double drag = 0.0;        // C_d [1/time]
  double mean_products = 0.0;  // marker-system products per step [-]
};

Scene oscillating_cylinder(int per_diameter, double box, int steps_per_period) {
  Scene scene;
  scene.source_file = "(oscillating cylinder)";
  const int n = static_cast<int>(std::lround(box * per_diameter));
  scene.domain = {box, box, n, n, false, false};
  scene.fluid.density = 1.0;
  scene.fluid.kinematic_viscosity = nu;
  scene.fluid.convection = FluidSpec::Convection::central;
  scene.run.end_time = periods * period;
  scene.run.time_step = period / steps_per_period;
  scene.ibm.coupling = IbmSpec::Coupling::no_slip;
  scene.ibm.constrained_velocity = IbmSpec::ConstrainedVelocity::faces;
  scene.ibm.slip_tolerance = 1e-4;
  scene.ibm.marker_retraction = retraction;
  BodySpec body;
  body.kind = BodySpec::Kind::prescribed;
  body.centre = {0.5 * box, 0.5 * box};
  body.diameter = diameter;
  body.n_surface_points = static_cast<int>(std::lround(pi * diameter * per_diameter));
  body.density = 1.0;
  body.oscillation_amplitude = {amplitude, 0.0};
  body.oscillation_period = period;
  body.oscillation_phase = -0.5 * pi;
  body.reference_speed = amplitude * omega;
  scene.bodies.push_back(body);
  return scene;
}

// Least-squares fit F = -C_m m_f dU/dt - C_d m_f U + c over the last period, the force of each
// step taken at its midpoint.
Fit measure(int per_diameter, double box, int steps_per_period) {
  Simulation sim(oscillating_cylinder(per_diameter, box, steps_per_period));
  const double dt = period / steps_per_period;
  const double mass = pi * 0.25 * diameter * diameter;  // m_f, rho = 1
  const int n_steps = periods * steps_per_period, first = (periods - 1) * steps_per_period;
  Eigen::MatrixXd basis(n_steps - first, 3);
  Eigen::VectorXd force(n_steps - first);
  Fit fit;
  for (int k = 0; k < n_steps; ++k) {
    const double t_mid = (k + 0.5) * dt;
    advance_one_step(sim, dt);
    if (k < first) continue;
    // U = A w sin(w t), dU/dt = A w^2 cos(w t).
    basis.row(k - first) << -mass * amplitude * omega * omega * std::cos(omega * t_mid),
        -mass * amplitude * omega * std::sin(omega * t_mid), 1.0;
    force(k - first) = sim.markers()[0].hydrodynamic_force[0];
  }
  const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(force);
  fit.added_mass = c[0];
  fit.drag = c[1];
  fit.mean_products = static_cast<double>(sim.stats().total_coupling_iterations) / n_steps;
  return fit;
}

}  // namespace

BOOST_AUTO_TEST_CASE(complex_bessel_functions_match_gsl_on_the_real_axis) {
  for (const double x : {0.5, 1.0, 3.0, 7.0}) {
    BOOST_TEST(std::abs(test::bessel_k(0, x) - gsl_sf_bessel_K0(x)) < 1e-12 * gsl_sf_bessel_K0(x));
    BOOST_TEST(std::abs(test::bessel_k(1, x) - gsl_sf_bessel_K1(x)) < 1e-12 * gsl_sf_bessel_K1(x));
  }
}

BOOST_AUTO_TEST_CASE(both_force_parts_converge_to_the_exact_ones) {
  const test::StokesCylinderForce exact = test::stokes_cylinder_force(0.5 * diameter, omega, nu);
  BOOST_TEST_MESSAGE("exact: C_m = " << exact.added_mass_coefficient << ", C_d = " << exact.drag_coefficient
                                     << " (|s| = 5, KC = " << 2 * pi * amplitude / diameter << ")");
  // The box's confinement, from the 8 D and 16 D boxes at D/h = 20.
  const Fit box8 = measure(20, 8.0, 100), box16 = measure(20, 16.0, 100);
  const double confinement_m = 4.0 / 3.0 * (box8.added_mass - box16.added_mass);
  const double confinement_d = 4.0 / 3.0 * (box8.drag - box16.drag);
  BOOST_TEST_MESSAGE("confinement of the 8 D box: C_m " << 100 * confinement_m / exact.added_mass_coefficient
                                                        << " %, C_d " << 100 * confinement_d / exact.drag_coefficient << " %");
  const std::vector<int> grids{10, 20, 40};
  std::vector<double> h, error_m, error_d;
  for (const int m : grids) {
    const Fit f = m == 20 ? box8 : measure(m, 8.0, 5 * m);
    h.push_back(diameter / m);
    error_m.push_back(std::abs((f.added_mass - confinement_m) / exact.added_mass_coefficient - 1.0));
    error_d.push_back(std::abs((f.drag - confinement_d) / exact.drag_coefficient - 1.0));
    BOOST_TEST_MESSAGE("D/h = " << m << ", " << 5 * m << " steps a period: C_m = " << f.added_mass - confinement_m
                                << " (error " << 100 * error_m.back() << " %), C_d = " << f.drag - confinement_d
                                << " (error " << 100 * error_d.back() << " %), " << f.mean_products
                                << " products a step");
    // The marker system's preconditioner, the body's own operator J_f P_0 S_f from the lattice
    // Green's function (sim/coupling/marker_preconditioner.hpp): 1.67, 1.00 and 1.00 products a
    // step measured; 10.7, 10.0 and 12.2 with J S and the leak, 21-29 without a preconditioner.
    BOOST_TEST(f.mean_products <= 2.0);
  }
  // Band [1, 3]: the diffuse interface is first order; with the retraction cancelling its leading
  // term the parts converge at 1.5-2.6 (measured), and an order above 3 would be errors cancelling
  // between grids, not convergence.
  const verification::OrderClaim claim{1.0, 1.0, 3.0, "h"};
  verification::append_convergence_csv("oscillating cylinder, added-mass part (Stokes 1851)", grids, h, error_m, claim);
  verification::append_convergence_csv("oscillating cylinder, Stokes-drag part (Stokes 1851)", grids, h, error_d, claim);
  for (const auto* error : {&error_m, &error_d})
    for (const double p : verification::pairwise_orders(h, *error)) {
      BOOST_TEST(p >= claim.asserted_min);
      BOOST_TEST(p <= claim.asserted_max);
    }
  BOOST_TEST(error_m.back() < 0.01);
  BOOST_TEST(error_d.back() < 0.01);
}
