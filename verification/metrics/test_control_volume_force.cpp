// Claims of the control-volume force (solver/metrics/control_volume_force.hpp), label unit:
//  - a uniform flow gives no force, to round-off;
//  - a pure pressure gradient G at rest gives -rho G times the area of the rectangle, to round-off;
//  - plane Poiseuille flow: the pressure term is -dp/dx L H, the viscous term the wall-shear-stress
//    difference nu (u'(y_top) - u'(y_bottom)) L of the analytic profile, and the force is zero, to
//    round-off (a quadratic profile is exact for the differences);
//  - a uniformly accelerating flow gives -rho a A (the rate-of-change term), to round-off;
//  - potential flow past a cylinder with circulation Gamma gives the Kutta-Joukowski force
//    (0, -rho U Gamma) at second order in h (least-squares slope over three grids, viscous terms
//    included: they integrate to zero for a potential flow);
//  - on the fluid solver's own flow driven from rest by a steady body force f (a stand-in for a
//    body), the balance returns the reaction -rho sum f h^2 of what lies inside within 0.1 %, and
//    apart from the transposed viscous part (O(h^2), not in the solver's Laplacian) the difference
//    is second order in dt;
//  - the rectangle around a body keeps the margin max(D/2, 6 h) and 2 cells from the box's sides;
//  - the time mean of two histories weights each row by its step.
#define BOOST_TEST_MODULE control_volume_force
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>
#include <functional>
#include <vector>

#include "../common/convergence.hpp"
#include "core/constants.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_solver.hpp"
#include "metrics/control_volume_force.hpp"

using namespace ibms;

namespace {

// Cell fields, face velocities and pressure sampled from functions of (x, y).
struct SampledFlow {
  CellField u, v, p;
  FaceField uf, vf;
  using Function = std::function<double(double, double)>;
  SampledFlow(const Grid& g, const Function& fu, const Function& fv, const Function& fp)
      : u(g), v(g), p(g), uf(FaceField::x_faces(g)), vf(FaceField::y_faces(g)) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        u(i, j) = fu(g.x_centre(i), g.y_centre(j));
        v(i, j) = fv(g.x_centre(i), g.y_centre(j));
        p(i, j) = fp(g.x_centre(i), g.y_centre(j));
      }
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i) uf(i, j) = fu(g.x_face(i), g.y_centre(j));
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) vf(i, j) = fv(g.x_centre(i), g.y_face(j));
  }
  FlowFields fields() const { return {u, v, uf, vf, p}; }
};

double rectangle_area(const Grid& g, const CellRectangle& r) {
  return (r.i_end - r.i_begin) * g.dx() * (r.j_end - r.j_begin) * g.dy();
}

}  // namespace

BOOST_AUTO_TEST_CASE(uniform_flow_gives_no_force) {
  const Grid g(40, 30, 2.0, 1.5);
  const SampledFlow flow(g, [](double, double) { return 0.7; }, [](double, double) { return -0.3; },
                         [](double, double) { return 2.5; });
  const CellRectangle r{5, 31, 4, 22};
  const ForceVector f = control_volume_force(g, r, flow.fields(), flow.fields(), 0.01, 1.3, 0.01);
  // Scale: rho U^2 times the rectangle's side, ~1.3 * 0.5 * 1.3.
  BOOST_TEST(std::abs(f[0]) < 1e-13);
  BOOST_TEST(std::abs(f[1]) < 1e-13);
}

BOOST_AUTO_TEST_CASE(pressure_gradient_gives_minus_gradient_times_area) {
  const Grid g(32, 24, 1.0, 0.75, false, false, -0.5, 0.25);
  const double gx = 3.0, gy = -1.25, rho = 1.7;
  const SampledFlow flow(g, [](double, double) { return 0.0; }, [](double, double) { return 0.0; },
                         [&](double x, double y) { return 4.0 + gx * x + gy * y; });
  const CellRectangle r{3, 29, 2, 19};
  const double area = rectangle_area(g, r);
  const ForceVector f = control_volume_force(g, r, flow.fields(), flow.fields(), 0.02, rho, 0.1);
  BOOST_TEST(f[0] == -rho * gx * area, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(f[1] == -rho * gy * area, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(poiseuille_flow_balances_pressure_against_wall_shear) {
  const double height = 0.41, u_max = 0.3, nu = 1e-3, rho = 1.0;
  const Grid g(88, 41, 2.2, height);
  const double dpdx = -8.0 * nu * u_max / (height * height);  // nu u'' = dp/dx (kinematic)
  const auto profile = [&](double, double y) { return 4.0 * u_max * y * (height - y) / (height * height); };
  const SampledFlow flow(g, profile, [](double, double) { return 0.0; }, [&](double x, double) { return dpdx * x; });
  const CellRectangle r{10, 50, 3, 30};
  const double length = g.x_face(r.i_end) - g.x_face(r.i_begin);
  const double y_bottom = g.y_face(r.j_begin), y_top = g.y_face(r.j_end);
  const auto shear = [&](double y) { return nu * 4.0 * u_max * (height - 2.0 * y) / (height * height); };
  const ControlVolumeTerms t = control_volume_terms(g, r, flow.fields(), nu);
  BOOST_TEST(t.pressure[0] == -dpdx * length * (y_top - y_bottom), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(t.viscous[0] == (shear(y_top) - shear(y_bottom)) * length, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(t.viscous_transpose[0]) < 1e-15);
  BOOST_TEST(std::abs(t.momentum_flux[0]) < 1e-15);
  const ForceVector f = control_volume_force(t, t, 0.01, rho);
  const double scale = std::abs(t.pressure[0]) * rho;
  BOOST_TEST(std::abs(f[0]) < 1e-12 * scale);
  BOOST_TEST(std::abs(f[1]) < 1e-12 * scale);
}

BOOST_AUTO_TEST_CASE(uniform_acceleration_gives_minus_rate_of_momentum) {
  const Grid g(30, 30, 1.0, 1.0);
  const double ax = 2.0, ay = -0.5, t0 = 0.3, dt = 0.01, rho = 0.9;
  const SampledFlow before(g, [&](double, double) { return ax * t0; }, [&](double, double) { return ay * t0; },
                           [](double, double) { return 1.0; });
  const SampledFlow after(g, [&](double, double) { return ax * (t0 + dt); },
                          [&](double, double) { return ay * (t0 + dt); }, [](double, double) { return 1.0; });
  const CellRectangle r{4, 20, 6, 26};
  const double area = rectangle_area(g, r);
  const ForceVector f = control_volume_force(g, r, before.fields(), after.fields(), 0.05, rho, dt);
  BOOST_TEST(f[0] == -rho * ax * area, boost::test_tools::tolerance(1e-11));
  BOOST_TEST(f[1] == -rho * ay * area, boost::test_tools::tolerance(1e-11));
}

BOOST_AUTO_TEST_CASE(potential_flow_with_circulation_gives_kutta_joukowski_at_second_order) {
  // w(z) = U (z + a^2/z) - (i Gamma / 2 pi) log z: counter-clockwise circulation Gamma, force on the
  // cylinder (0, -rho U Gamma); p from Bernoulli; the inside (r < a) is never read by the sides.
  const double a = 0.25, speed = 1.0, gamma = 0.8, rho = 1.2, nu = 0.01;
  const auto velocity = [&](double x, double y) {
    const std::complex<double> z(x, y);
    if (std::abs(z) < a) return std::complex<double>(0.0, 0.0);
    const std::complex<double> i(0.0, 1.0);
    return std::conj(speed * (1.0 - a * a / (z * z)) - i * gamma / (2.0 * pi * z));  // u + i v
  };
  std::vector<double> h, error_lift, error_drag;
  std::vector<int> n_cells;
  const double lift = -rho * speed * gamma;
  for (int n : {64, 128, 256}) {
    const Grid g(n, n, 2.0, 2.0, false, false, -1.0, -1.0);
    const SampledFlow flow(g, [&](double x, double y) { return velocity(x, y).real(); },
                           [&](double x, double y) { return velocity(x, y).imag(); },
                           [&](double x, double y) { return 0.5 * (speed * speed - std::norm(velocity(x, y))); });
    const CellRectangle r = control_volume_around(g, {-a, -a}, {a, a}, 2 * a);
    const ForceVector f = control_volume_force(g, r, flow.fields(), flow.fields(), nu, rho, 0.01);
    BOOST_TEST_MESSAGE("N = " << n << ": force " << f[0] << ", " << f[1] << " (Kutta-Joukowski 0, " << lift << ")");
    h.push_back(g.dx());
    n_cells.push_back(n);
    error_lift.push_back(std::abs(f[1] / lift - 1.0));
    error_drag.push_back(std::abs(f[0] / lift));
  }
  BOOST_TEST_MESSAGE(verification::convergence_table(
      "control-volume lift of potential flow with circulation, relative error", n_cells, h, error_lift));
  const ObservedOrder order = verification::finest_three_fit(h, error_lift);
  BOOST_TEST(order.order >= 1.9);
  BOOST_TEST(order.standard_error <= verification::max_order_standard_error);
  BOOST_TEST(error_lift.back() < 1e-3);
  BOOST_TEST(error_drag.back() < 1e-3);
}

namespace {

// A periodic channel (walls at y = 0, 1) driven from rest by a steady Gaussian body force f at
// (1, 0.5), up to t = 0.4 (velocities up to ~0.5, cell Reynolds number ~1): the control-volume
// force of the last step on the rectangle around the blob, and the reaction -rho sum f h^2 of the
// force inside it.
struct ForcedFlow {
  ForceVector force, force_without_transpose, reaction;
};
ForcedFlow forced_flow(int steps) {
  const double dt = 0.4 / steps;
  const Grid g(64, 32, 2.0, 1.0, /*periodic_x=*/true, false);
  FluidBoundaries bc;
  const double nu = 0.02, rho = 1.1;
  FluidSolver solver(g, nu, bc);
  FluidState state = solver.make_state();
  solver.initialise_faces(state);
  CellField fx(g), fy(g);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double dx = g.x_centre(i) - 1.0, dy = g.y_centre(j) - 0.5;
      const double bump = std::exp(-(dx * dx + dy * dy) / (0.1 * 0.1));
      fx(i, j) = 20.0 * bump;
      fy(i, j) = 8.0 * bump * (1.0 + dx / 0.1);  // a y component too, not symmetric
    }
  ForcedFlow out{};
  const CellRectangle r = control_volume_around(g, {0.8, 0.3}, {1.2, 0.7}, 0.4);
  for (int j = r.j_begin; j < r.j_end; ++j)
    for (int i = r.i_begin; i < r.i_end; ++i) {
      out.reaction[0] -= rho * fx(i, j) * g.cell_area();
      out.reaction[1] -= rho * fy(i, j) * g.cell_area();
    }
  const auto fields = [&]() { return FlowFields{state.velocity_x, state.velocity_y, state.velocity_face_x,
                                                state.velocity_face_y, state.pressure}; };
  ControlVolumeTerms before = control_volume_terms(g, r, fields(), nu);
  for (int k = 0; k < steps; ++k) {
    solver.predict_momentum(state, dt, &fx, &fy);
    solver.project_smac(state, dt);
    const ControlVolumeTerms after = control_volume_terms(g, r, fields(), nu);
    out.force = out.force_without_transpose = control_volume_force(before, after, dt, rho);
    for (int d = 0; d < 2; ++d)
      out.force_without_transpose[d] -= rho * 0.5 * (before.viscous_transpose[d] + after.viscous_transpose[d]);
    before = after;
  }
  return out;
}

double relative_distance(const ForceVector& a, const ForceVector& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]) / std::hypot(b[0], b[1]);
}

}  // namespace

BOOST_AUTO_TEST_CASE(forced_solver_flow_returns_the_reaction_at_second_order_in_time) {
  // Summed over the rectangle, the solver's step is exactly a momentum balance with the AB2 flux,
  // the Crank-Nicolson viscous flux of (grad u).n and p^{n+1}; the time-centred balance differs from
  // it by O(dt^2), and the transposed viscous part, absent from the solver, adds an O(h^2) term.
  std::vector<double> h, e;
  std::vector<int> n;
  double worst_full = 0.0;
  for (int steps : {20, 40, 80}) {
    const ForcedFlow f = forced_flow(steps);
    const double mismatch = relative_distance(f.force_without_transpose, f.reaction);
    worst_full = std::max(worst_full, relative_distance(f.force, f.reaction));
    BOOST_TEST_MESSAGE(steps << " steps to t = 0.4: force " << f.force[0] << ", " << f.force[1] << ", reaction "
                             << f.reaction[0] << ", " << f.reaction[1] << "; relative difference "
                             << relative_distance(f.force, f.reaction) << ", without the transposed viscous part "
                             << mismatch);
    h.push_back(0.4 / steps);
    n.push_back(steps);
    e.push_back(mismatch);
  }
  BOOST_TEST_MESSAGE(verification::convergence_table(
      "control-volume force of the forced solver flow against the reaction, relative difference, dt study", n, h, e,
      {2.0, 1.8, 2.0 + verification::max_order_excess, "dt"}));  // h holds the time step here
  BOOST_TEST(verification::finest_three_slope(h, e) >= 1.8);
  BOOST_TEST(verification::finest_three_slope(h, e) <= 2.0 + verification::max_order_excess);
  // The whole balance within 0.1 % of the reaction at every dt: a tenth of the 1 % at which the
  // checks compare it with the immersed-boundary force (measured: 2.5e-4, 1.6e-4, 1.1e-4).
  BOOST_TEST(worst_full < 1e-3);
}

BOOST_AUTO_TEST_CASE(rectangle_keeps_its_margin_and_stays_inside_the_box) {
  const Grid g(100, 50, 2.0, 1.0);  // h = 0.02
  // D = 0.19: margin D/2 = 4.75 h < 6 h = 0.12.
  CellRectangle r = control_volume_around(g, {0.905, 0.405}, {1.095, 0.595}, 0.19);
  BOOST_TEST(r.i_begin == 39);  // floor((0.905 - 0.12) / 0.02)
  BOOST_TEST(r.i_end == 61);    // ceil((1.095 + 0.12) / 0.02)
  BOOST_TEST(r.j_begin == 14);
  BOOST_TEST(r.j_end == 36);
  BOOST_TEST(control_volume_clearance(g, r, {0.905, 0.405}, {1.095, 0.595}) >= 0.12);
  // D = 0.4: margin D/2.
  r = control_volume_around(g, {0.8, 0.3}, {1.2, 0.7}, 0.4);
  BOOST_TEST(control_volume_clearance(g, r, {0.8, 0.3}, {1.2, 0.7}) >= 0.2 - 1e-12);
  // Next to the bottom-left corner: clipped to 2 cells from the sides.
  r = control_volume_around(g, {0.01, 0.01}, {0.21, 0.21}, 0.2);
  BOOST_TEST(r.i_begin == 2);
  BOOST_TEST(r.j_begin == 2);
  BOOST_TEST(control_volume_clearance(g, r, {0.01, 0.01}, {0.21, 0.21}) < 0.0);
  r = control_volume_around(g, {1.9, 0.9}, {1.99, 0.99}, 0.09);
  BOOST_TEST(r.i_end == g.nx - 2);
  BOOST_TEST(r.j_end == g.ny - 2);
  // A non-finite position (a blown-up body) still gives a rectangle inside the box.
  r = control_volume_around(g, {NAN, 0.4}, {NAN, 0.6}, 0.2);
  BOOST_TEST(r.i_begin >= 2);
  BOOST_TEST(r.i_end <= g.nx - 2);
  BOOST_CHECK_THROW(control_volume_terms(g, CellRectangle{0, 10, 2, 10}, SampledFlow(g, [](double, double) { return 0.0; },
                        [](double, double) { return 0.0; }, [](double, double) { return 0.0; }).fields(), 0.1),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(time_mean_weights_each_row_by_its_step) {
  const std::vector<double> time{0.0, 1.0, 2.0, 4.0, 5.0};
  const std::vector<double> ib{9.0, 1.0, 2.0, 3.0, 4.0}, cv{9.0, 1.1, 2.0, 3.0, 4.0};
  const DragAgreement m = mean_drag_agreement(time, ib, cv, 2.0);
  // Rows at t = 2, 4, 5 with steps 1, 2, 1: (2 + 6 + 4) / 4 = 3.
  BOOST_TEST(m.immersed_boundary == 3.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(m.relative_difference == 0.0, boost::test_tools::tolerance(1e-14));
  const DragAgreement all = mean_drag_agreement(time, ib, cv, 0.0);  // the first row has no step: left out
  BOOST_TEST(all.control_volume - all.immersed_boundary == 0.1 / 5.0, boost::test_tools::tolerance(1e-12));
  const DragAgreement last = final_drag_agreement(ib, cv);
  BOOST_TEST(last.relative_difference == 0.0);
  BOOST_CHECK_THROW(mean_drag_agreement(time, ib, cv, 4.5), std::invalid_argument);
}
