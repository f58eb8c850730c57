// Claims, label unit:
//  - the FFTW solver with mixed ends (Neumann at one end of a direction, Dirichlet at the other:
//    DCT-IV / DST-IV) solves (a I + b L) q = r to round-off, for the pressure (outflow = Dirichlet)
//    and the velocity (outflow = Neumann) problems, with every combination of ends on both axes;
//  - plane Poiseuille flow (parabolic inflow, outflow, walls) is a steady state of the discrete
//    scheme to round-off with the quadratic wall closure: u, v and p stay exact for 200 steps;
//  - the net volume flux through the box's sides is 0 to round-off after every step, also while the
//    inflow ramps up from rest, and the outflow carries exactly what the inflow brings;
//  - the scene's inflow profiles and time factors give the stated values.
// Checks docs/method.md §2.5's inflow, outflow and periodic sides (their ghost rules in
// docs/open-boundaries.md).
#define BOOST_TEST_MODULE open_boundaries
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/constants.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/spectral_solver.hpp"

using namespace ibms;

namespace {

using B = SpectralBoundary;

// (a I + b L) q with the ghost rules of the four ends: q_g = q (Neumann), -q (Dirichlet), wrap.
std::vector<double> apply(const Grid& g, const B ends[4], double a, double b, const std::vector<double>& q) {
  const auto at = [&](int i, int j) -> double {
    double sign = 1.0;
    if (i < 0) { if (ends[0] == B::periodic) i += g.nx; else { sign *= ends[0] == B::dirichlet ? -1 : 1; i = 0; } }
    if (i >= g.nx) { if (ends[1] == B::periodic) i -= g.nx; else { sign *= ends[1] == B::dirichlet ? -1 : 1; i = g.nx - 1; } }
    if (j < 0) { if (ends[2] == B::periodic) j += g.ny; else { sign *= ends[2] == B::dirichlet ? -1 : 1; j = 0; } }
    if (j >= g.ny) { if (ends[3] == B::periodic) j -= g.ny; else { sign *= ends[3] == B::dirichlet ? -1 : 1; j = g.ny - 1; } }
    return sign * q[g.index(i, j)];
  };
  std::vector<double> r(q.size());
  const double ax = 1.0 / (g.dx() * g.dx()), ay = 1.0 / (g.dy() * g.dy());
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      r[g.index(i, j)] = a * at(i, j) + b * ((at(i - 1, j) - 2 * at(i, j) + at(i + 1, j)) * ax +
                                             (at(i, j - 1) - 2 * at(i, j) + at(i, j + 1)) * ay);
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(mixed_ends_solve_to_round_off) {
  const B kinds[] = {B::neumann, B::dirichlet};
  int cases = 0;
  for (B left : kinds) for (B right : kinds) for (B bottom : {B::neumann, B::dirichlet, B::periodic})
    for (B top : kinds) {
      const B ends[4] = {left, right, bottom, bottom == B::periodic ? B::periodic : top};
      if (bottom == B::periodic && top == B::dirichlet) continue;  // one periodic y case suffices
      const Grid g(20, 13, 2.2, 0.41, false, bottom == B::periodic);
      std::mt19937 gen(5 + cases);
      std::uniform_real_distribution<double> dist(-1.0, 1.0);
      std::vector<double> q(g.n_cells());
      for (double& x : q) x = dist(gen);
      for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{1.0, -0.003}}) {
        const bool singular = a == 0.0 && std::none_of(ends, ends + 4, [](B e) { return e == B::dirichlet; });
        if (singular) continue;  // the closed-box solver, test_spectral_solver
        const std::vector<double> r = apply(g, ends, a, b, q);
        SpectralSolver solver(g, ends[0], ends[1], ends[2], ends[3]);
        std::vector<double> solution(g.n_cells());
        solver.solve(a, b, r.data(), solution.data());
        double error = 0;
        for (std::size_t k = 0; k < q.size(); ++k) error = std::max(error, std::abs(solution[k] - q[k]));
        BOOST_TEST_MESSAGE("ends " << int(ends[0]) << int(ends[1]) << int(ends[2]) << int(ends[3]) << " a = " << a
                                   << ": max |q - q_exact| = " << error);
        // Round-off of two transforms of 260 values, condition number <= ~1e4: 1e-11.
        BOOST_TEST(error < 1e-11);
        ++cases;
      }
    }
  BOOST_TEST(cases == 38);  // 20 sets of ends x (Poisson, Helmholtz) minus the 2 singular ones
}

BOOST_AUTO_TEST_CASE(inflow_profiles_and_time_factors) {
  InflowProfile p;
  p.shape = InflowProfile::Shape::parabolic;
  p.velocity = 1.5;
  BOOST_TEST(std::abs(p.at(0.205, 0.41, 0.0) - 1.5) < 1e-15);  // peak at the middle
  BOOST_TEST(p.at(0.0, 0.41, 0.0) == 0.0);
  BOOST_TEST(std::abs(p.mean_at(0.0) - 1.0) < 1e-15);          // DFG 2D-2: U_mean = 2/3 U_max
  p.factor.kind = TimeFactor::Kind::ramp;
  p.factor.ramp_time = 2.0;
  BOOST_TEST(std::abs(p.at(0.205, 0.41, 0.5) - 0.375) < 1e-15);
  BOOST_TEST(std::abs(p.at(0.205, 0.41, 7.0) - 1.5) < 1e-15);
  p.factor.kind = TimeFactor::Kind::sinusoidal;  // DFG 2D-3: sin(pi t / 8)
  p.factor.offset = 0.0;
  p.factor.amplitude = 1.0;
  p.factor.period = 16.0;
  BOOST_TEST(std::abs(p.at(0.205, 0.41, 4.0) - 1.5) < 1e-14);
  BOOST_TEST(std::abs(p.at(0.205, 0.41, 2.0) - 1.5 * std::sin(pi / 4)) < 1e-14);
}

namespace {

// Channel [0, 2] x [0, 1], parabolic inflow on the left (peak 1), outflow on the right, walls.
constexpr double nu = 0.05, peak = 1.0, length = 2.0;
double poiseuille_u(double y) { return 4.0 * peak * y * (1.0 - y); }
double poiseuille_p(double x) { return 8.0 * nu * peak * (length - x); }  // p_x = nu u_yy, p(L) = 0

FluidBoundaries channel(TimeFactor factor = {}) {
  FluidBoundaries bc;
  bc.left.kind = SideKind::inflow;
  bc.left.inflow.shape = InflowProfile::Shape::parabolic;
  bc.left.inflow.velocity = peak;
  bc.left.inflow.factor = factor;
  bc.right.kind = SideKind::outflow;
  return bc;
}

}  // namespace

BOOST_AUTO_TEST_CASE(plane_poiseuille_is_a_discrete_steady_state_to_round_off) {
  const Grid g(48, 24, length, 1.0);
  FluidSolver solver(g, nu, channel(), FluidSchemes{ConvectionScheme::central, /*quadratic_wall=*/true});
  FluidState s = solver.make_state();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      s.velocity_x(i, j) = poiseuille_u(g.y_centre(j));
      s.pressure(i, j) = poiseuille_p(g.x_centre(i));
    }
  solver.initialise_faces(s);
  const double dt = 0.5 * g.dx() / peak;
  double worst_u = 0, worst_v = 0, worst_p = 0, worst_flux = 0;
  for (int step = 0; step < 200; ++step) {
    solver.predict_momentum(s, dt, nullptr, nullptr);
    solver.project_smac(s, dt);
    worst_flux = std::max(worst_flux, std::abs(net_inflow(g, s.velocity_face_x, s.velocity_face_y)));
  }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      worst_u = std::max(worst_u, std::abs(s.velocity_x(i, j) - poiseuille_u(g.y_centre(j))));
      worst_v = std::max(worst_v, std::abs(s.velocity_y(i, j)));
      worst_p = std::max(worst_p, std::abs(s.pressure(i, j) - poiseuille_p(g.x_centre(i))));
    }
  BOOST_TEST_MESSAGE("Poiseuille, 200 steps, quadratic wall closure: max |u - u_exact| = "
                     << worst_u << ", max |v| = " << worst_v << ", max |p - p_exact| = " << worst_p
                     << ", max |net flux| = " << worst_flux);
  // Round-off: values O(1), 200 steps of O(1e3) operations per value: 1e-12.
  BOOST_TEST(worst_u < 1e-12);
  BOOST_TEST(worst_v < 1e-12);
  BOOST_TEST(worst_p < 1e-12);
  BOOST_TEST(worst_flux < 1e-13);
}

BOOST_AUTO_TEST_CASE(outflow_carries_the_inflow_every_step_while_it_ramps_up) {
  const Grid g(40, 20, length, 1.0);
  TimeFactor ramp;
  ramp.kind = TimeFactor::Kind::ramp;
  ramp.ramp_time = 0.5;
  FluidSolver solver(g, nu, channel(ramp));
  FluidState s = solver.make_state();
  solver.initialise_faces(s);
  const double dt = 0.4 * g.dx() / peak;
  double worst = 0, worst_inflow = 0, last_inflow = 0;
  for (int step = 0; step < 150; ++step) {
    solver.predict_momentum(s, dt, nullptr, nullptr);
    const ProjectionStats stats = solver.project_smac(s, dt);
    const double in = side_inflow(g, Side::left, s.velocity_face_x, s.velocity_face_y);
    const double out = -side_inflow(g, Side::right, s.velocity_face_x, s.velocity_face_y);
    // The inflow is the discrete profile: the midpoint sum of 4 y (1 - y) = 2/3 + h^2/3.
    const double expected = peak * ramp.at(s.time) * (2.0 / 3.0 + g.dy() * g.dy() / 3.0);
    worst = std::max(worst, std::abs(out - in));
    worst_inflow = std::max(worst_inflow, std::abs(in - expected));
    BOOST_TEST(stats.max_divergence_after < 1e-11);
    last_inflow = in;
  }
  BOOST_TEST_MESSAGE("ramped inflow, 150 steps: max |outflow - inflow| = " << worst
                     << ", max |inflow - discrete profile flux| = " << worst_inflow << ", final inflow " << last_inflow);
  BOOST_TEST(worst < 1e-13);
  BOOST_TEST(worst_inflow < 1e-14);
  BOOST_TEST(last_inflow > 0.6);  // the ramp ended: the full flux passes
}
