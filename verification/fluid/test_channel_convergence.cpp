// Claims, label convergence:
//  - with an inflow side (x = 0, velocity data), an outflow side (x = 1: zero normal gradient,
//    p = 0) and walls, the solver keeps second order in space for u, v and p in the L2 and max
//    norms (finest-three slope >= 1.9, docs/design.md §6) on the manufactured solution of
//    channel_solution.hpp, steady and unsteady (t = 1); the pressure, which needs no mean
//    removal (p = 0 at the outflow fixes it), only >= 1.85 in L2 and first order in the max norm,
//    because of a layer at the corners where the inflow meets a wall (see mms_study);
//  - plane Poiseuille flow from rest (parabolic inflow, linear wall closure) reaches a steady
//    state whose error against the exact parabola and linear pressure falls at second order.
#define BOOST_TEST_MODULE channel_convergence
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../common/convergence.hpp"
#include "../common/manufactured_run.hpp"
#include "channel_solution.hpp"
#include "fluid/fluid_solver.hpp"

using namespace ibms;
using verification::ChannelSolution;

namespace {

// The errors of common/manufactured_run.hpp, and the pressure's max norm away from the corners.
struct Errors : verification::ManufacturedErrors {
  double p_max_away = 0;
};

// Cells farther than this from both corners where the inflow meets a wall count for p_max_away.
constexpr double corner_radius = 0.25;

void check_order(const std::string& name, const std::vector<int>& n, const std::vector<double>& h,
                 const std::vector<double>& e, double required) {
  BOOST_TEST_MESSAGE(verification::convergence_table(name, n, h, e, {2.0, required, 2.0 + verification::max_order_excess, "h"}));
  const ObservedOrder fit = verification::finest_three_fit(h, e);
  BOOST_TEST(fit.order >= required);
  BOOST_TEST(fit.order <= 2.0 + verification::max_order_excess);
  BOOST_TEST(fit.standard_error <= verification::max_order_standard_error);
}

Errors run_mms(const ChannelSolution& ms, int n, double dt, double end_time, double steady_tolerance) {
  const Grid g(n, n, 1.0, 1.0);
  FluidBoundaries bc;
  bc.left.kind = SideKind::inflow;
  bc.left.prescribed = [&ms](double x, double y, double t) { return std::array<double, 2>{ms.u(x, y, t), ms.v(x, y, t)}; };
  bc.right.kind = SideKind::outflow;
  FluidSolver solver(g, ms.viscosity, bc);
  FluidState s = solver.make_state();
  verification::run_manufactured(ms, g, solver, s, dt, end_time, steady_tolerance);
  // p = 0 at the outflow fixes the pressure: no mean removed.
  Errors e{verification::manufactured_errors(ms, g, s, dt, /*remove_pressure_mean=*/false), /*p_max_away=*/0.0};
  const double t_p = s.time - 0.5 * dt;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = g.x_centre(i), y = g.y_centre(j);
      const double ep = std::abs(s.pressure(i, j) - ms.p(x, y, t_p));
      if (std::hypot(x, y) > corner_radius && std::hypot(x, 1.0 - y) > corner_radius)
        e.p_max_away = std::max(e.p_max_away, std::isfinite(ep) ? ep : HUGE_VAL);
    }
  return e;
}

void mms_study(bool steady) {
  ChannelSolution ms;
  ms.steady = steady;
  const std::vector<int> grids{16, 32, 64, 128};
  std::vector<double> h, ul2, umax, vl2, vmax, pl2, pmax, pmax_away;
  for (int n : grids) {
    const double dt = 0.25 / n;  // CFL about 0.25: the time error falls like h^2 too
    const Errors e = steady ? run_mms(ms, n, dt, 40.0, 1e-9) : run_mms(ms, n, dt, 1.0, 0.0);
    h.push_back(1.0 / n);
    ul2.push_back(e.u_l2); umax.push_back(e.u_max);
    vl2.push_back(e.v_l2); vmax.push_back(e.v_max);
    pl2.push_back(e.p_l2); pmax.push_back(e.p_max); pmax_away.push_back(e.p_max_away);
  }
  const std::string kind = steady ? "channel MMS (inflow, outflow, walls), steady, " : "channel MMS, unsteady (t = 1), ";
  check_order(kind + "u, L2 norm", grids, h, ul2, 1.9);
  check_order(kind + "u, max norm", grids, h, umax, 1.9);
  check_order(kind + "v, L2 norm", grids, h, vl2, 1.9);
  check_order(kind + "v, max norm", grids, h, vmax, 1.9);
  // The pressure has an O(h) error in a layer of a few cells at the two corners where the inflow
  // meets a wall (measured: error x N there is -0.21 at N = 32 and -0.24 at N = 64, the same shape
  // in cell units; it does not depend on dt, nor go away with the quadratic closure on every
  // Dirichlet side or with a quadratic pressure ghost at the walls). So the max norm over the whole
  // box is first order (measured slope 1.06 steady, 1.03 unsteady); the L2 norm (1.92 steady, 1.88
  // unsteady) and the max norm farther than 0.25 from those corners (1.87, 1.88) stay below
  // docs/design.md §6's 1.9 because the corner error reaches into the box. Asserted at the measured
  // orders less about 0.03: second order in pressure is missed here, as
  // docs/open-boundaries.md states, not a claim of second order.
  check_order(kind + "p, L2 norm", grids, h, pl2, 1.85);
  check_order(kind + "p, max norm", grids, h, pmax, 0.95);
  check_order(kind + "p, max norm farther than 0.25 from the inflow-wall corners", grids, h, pmax_away, 1.85);
}

}  // namespace

BOOST_AUTO_TEST_CASE(forcing_matches_finite_differences_of_the_exact_solution) {
  // The hand-written derivatives of channel_solution.hpp against central differences of u, v, p.
  ChannelSolution ms;
  ms.steady = false;
  const double d = 1e-4;
  double worst = 0;
  for (double x : {0.0, 0.23, 0.61, 0.97})
    for (double y : {0.05, 0.4, 0.77})
      for (double t : {0.0, 0.7}) {
        const auto u = [&](double a, double b, double c) { return ms.u(a, b, c); };
        const auto v = [&](double a, double b, double c) { return ms.v(a, b, c); };
        const auto p = [&](double a, double b, double c) { return ms.p(a, b, c); };
        const auto dx = [&](auto f) { return (f(x + d, y, t) - f(x - d, y, t)) / (2 * d); };
        const auto dy = [&](auto f) { return (f(x, y + d, t) - f(x, y - d, t)) / (2 * d); };
        const auto dt = [&](auto f) { return (f(x, y, t + d) - f(x, y, t - d)) / (2 * d); };
        const auto lap = [&](auto f) {
          return (f(x + d, y, t) + f(x - d, y, t) + f(x, y + d, t) + f(x, y - d, t) - 4 * f(x, y, t)) / (d * d);
        };
        const double fx = dt(u) + ms.u(x, y, t) * dx(u) + ms.v(x, y, t) * dy(u) + dx(p) - ms.viscosity * lap(u);
        const double fy = dt(v) + ms.u(x, y, t) * dx(v) + ms.v(x, y, t) * dy(v) + dy(p) - ms.viscosity * lap(v);
        const double div = dx(u) + dy(v);
        worst = std::max({worst, std::abs(fx - ms.force_x(x, y, t)), std::abs(fy - ms.force_y(x, y, t)), std::abs(div)});
      }
  BOOST_TEST_MESSAGE("max |forcing - finite differences| (and |div u|) = " << worst);
  BOOST_TEST(worst < 1e-5);  // O(d^2) truncation times fourth derivatives O(1e2), plus 1e-16 / d^2
  // The outflow conditions hold exactly: du/dx = dv/dx = 0 and p = 0 at x = 1.
  for (double y : {0.1, 0.5, 0.9}) {
    BOOST_TEST(ChannelSolution::g1(1.0) == 0.0);
    BOOST_TEST(ChannelSolution::g2(1.0) == 0.0);
    BOOST_TEST(ms.p(1.0, y, 0.3) == 0.0);
  }
}

BOOST_AUTO_TEST_CASE(steady_channel_mms_is_second_order) { mms_study(true); }

BOOST_AUTO_TEST_CASE(unsteady_channel_mms_is_second_order) { mms_study(false); }

BOOST_AUTO_TEST_CASE(poiseuille_from_rest_converges_at_second_order) {
  // Channel [0, 2] x [0, 1], nu = 0.2 (Re = 5 on the peak speed 1 and the width), parabolic
  // inflow ramped over t = 0.5, linear wall closure: the discrete fully developed profile is the
  // parabola shifted by C h^2 / 4 (C = 4), reached downstream of an entrance region.
  const double nu = 0.2;
  const std::vector<int> grids{8, 16, 32, 64};
  std::vector<double> h, eu, ep;
  for (int n : grids) {
    const Grid g(2 * n, n, 2.0, 1.0);
    FluidBoundaries bc;
    bc.left.kind = SideKind::inflow;
    bc.left.inflow.shape = InflowProfile::Shape::parabolic;
    bc.left.inflow.velocity = 1.0;
    bc.left.inflow.factor.kind = TimeFactor::Kind::ramp;
    bc.left.inflow.factor.ramp_time = 0.5;
    bc.right.kind = SideKind::outflow;
    FluidSolver solver(g, nu, bc);
    FluidState s = solver.make_state();
    solver.initialise_faces(s);
    const double dt = 0.5 * g.dx();
    long steps = 0;
    for (; steps < 200000; ++steps) {
      solver.predict_momentum(s, dt, nullptr, nullptr);
      const ProjectionStats stats = solver.project_smac(s, dt);
      if (s.time > 1.0 && stats.max_velocity_change / (dt * stats.max_velocity) < 1e-10) break;
    }
    double su = 0, sp = 0, mu = 0, mp = 0;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double y = g.y_centre(j), x = g.x_centre(i);
        const double du = s.velocity_x(i, j) - 4.0 * y * (1.0 - y);
        const double dp = s.pressure(i, j) - 8.0 * nu * (2.0 - x);
        su += du * du; sp += dp * dp;
        mu = std::max(mu, std::abs(du)); mp = std::max(mp, std::abs(dp));
      }
    BOOST_TEST_MESSAGE("Poiseuille N = " << n << ": steady after " << steps << " steps (t = " << s.time
                                         << "), max |u - u_exact| = " << mu << ", max |p - p_exact| = " << mp);
    h.push_back(1.0 / n);
    eu.push_back(std::sqrt(su / g.n_cells()));
    ep.push_back(std::sqrt(sp / g.n_cells()));
  }
  check_order("Poiseuille from rest, linear wall closure, u, L2 norm", grids, h, eu, 1.9);
  check_order("Poiseuille from rest, linear wall closure, p, L2 norm", grids, h, ep, 1.9);
}
