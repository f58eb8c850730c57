// Claims: after the SMAC projection the face velocities are divergence-free to round-off relative
// to the divergence before projection (docs/method.md §2.3: the Poisson operator is exactly D G_f),
// for walls, a moving lid and periodic boundaries; and plane Couette flow driven by a moving wall
// is a discrete steady solution to round-off (the wall shift of the Helmholtz solve is exact).
// The Couette flow checks docs/method.md §2.5's wall rule: a moving wall enters through the ghost
// 2 u_w - u_int and the wall's face-normal velocity 0.
#define BOOST_TEST_MODULE projection
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "fluid/fluid_solver.hpp"
#include "fluid/operators.hpp"

using namespace ibms;

namespace {

void randomise(const Grid& g, FluidState& s, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      s.velocity_x(i, j) = dist(gen);
      s.velocity_y(i, j) = dist(gen);
      s.pressure(i, j) = dist(gen);
    }
}

}  // namespace

BOOST_AUTO_TEST_CASE(projected_face_velocity_is_divergence_free) {
  struct Case { const char* name; bool px, py; double lid; };
  for (const Case& c : {Case{"walls, moving lid", false, false, 1.0}, Case{"periodic box", true, true, 0.0},
                        Case{"periodic x, walls y with lid", true, false, 1.0}}) {
    const Grid g(48, 40, 1.0, 0.8, c.px, c.py);
    FluidBoundaries bc;
    if (!c.py) bc.top.speed = c.lid;
    FluidSolver solver(g, 0.01, bc);
    FluidState s = solver.make_state();
    randomise(g, s, 42);
    solver.initialise_faces(s);
    for (int step = 0; step < 5; ++step) {
      solver.predict_momentum(s, 0.002, nullptr, nullptr);
      // An arbitrary (non-solenoidal) forcing on u* stands in for the immersed boundary.
      solver.velocity_star_x()(10, 10) += 0.3;
      const ProjectionStats stats = solver.project_smac(s, 0.002);
      const double ratio = stats.max_divergence_after / stats.max_divergence_before;
      BOOST_TEST_MESSAGE(c.name << ", step " << step << ": max|DU*| = " << stats.max_divergence_before
                                << ", max|DU^{n+1}| = " << stats.max_divergence_after << ", ratio " << ratio
                                << ", removed mean " << stats.removed_mean);
      // Two 2D transforms of ~2000 values: round-off ~1e-15 x log N relative; 1e-12 leaves margin.
      BOOST_TEST(ratio < 1e-12);
      // Wall face velocities are zero, so the pure Neumann rhs is compatible to round-off.
      BOOST_TEST(std::abs(stats.removed_mean) < 1e-12 * stats.max_divergence_before / 0.002);
    }
  }
}

BOOST_AUTO_TEST_CASE(plane_couette_flow_is_a_discrete_steady_state) {
  // Periodic in x, bottom wall at rest, top wall moving at U: u = U y / H exactly (linear, so the
  // second-order operators reproduce it), v = 0, p = const.
  const Grid g(16, 24, 2.0, 1.0, /*per_x=*/true, /*per_y=*/false);
  FluidBoundaries bc;
  bc.top.speed = 1.5;
  FluidSolver solver(g, 0.05, bc);
  FluidState s = solver.make_state();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) s.velocity_x(i, j) = 1.5 * g.y_centre(j);
  solver.initialise_faces(s);
  for (int step = 0; step < 50; ++step) {
    solver.predict_momentum(s, 0.01, nullptr, nullptr);
    solver.project_smac(s, 0.01);
  }
  double error = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      error = std::max({error, std::abs(s.velocity_x(i, j) - 1.5 * g.y_centre(j)), std::abs(s.velocity_y(i, j))});
  BOOST_TEST_MESSAGE("Couette: max error after 50 steps = " << error);
  BOOST_TEST(error < 1e-13);  // round-off on O(1) values
}

// The pressure update must stay stable where the compact rotational form of docs/method.md is not
// (nu dt/h^2 > 1/4, README "Departures"): a checkerboard pressure perturbation at nu dt/h^2 = 10
// must decay instead of growing by 4 nu dt/h^2 = 40 per step.
BOOST_AUTO_TEST_CASE(checkerboard_pressure_mode_decays_at_large_viscous_number) {
  const Grid g(32, 32, 1.0, 1.0);
  const double nu = 1.0, dt = 10.0 * g.dx() * g.dx() / nu;
  FluidSolver solver(g, nu, FluidBoundaries{});
  FluidState s = solver.make_state();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) s.pressure(i, j) = ((i + j) % 2 == 0) ? 1.0 : -1.0;
  double p_max = 0;
  for (int step = 0; step < 20; ++step) {
    solver.predict_momentum(s, dt, nullptr, nullptr);
    solver.project_smac(s, dt);
  }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) p_max = std::max(p_max, std::abs(s.pressure(i, j)));
  BOOST_TEST_MESSAGE("max |p| after 20 steps at nu dt/h^2 = 10, from 1: " << p_max);
  BOOST_TEST(p_max < 1.0);  // decayed (the compact rotational update would give ~40^20)
}

// A fixed time scale tau of the momentum interpolation (FluidSolver::set_interpolation_time,
// docs/method.md §2.3): the projection solves D (dt M A + tau (I - M A)) G_f phi = D U*, which the
// transforms diagonalise, so the faces are divergence-free to round-off for tau above and below
// the step, with walls, periodic sides and an inflow-outflow channel; and after every step the
// faces differ from the mean of the cells by -tau (I - M A) G_f p^{n+1} (no force), whatever dt.
BOOST_AUTO_TEST_CASE(fixed_interpolation_time_keeps_faces_divergence_free) {
  struct Case { const char* name; bool px, py; double lid; bool channel; };
  for (const Case& c : {Case{"walls, moving lid", false, false, 1.0, false}, Case{"periodic box", true, true, 0.0, false},
                        Case{"periodic x, walls y with lid", true, false, 1.0, false},
                        Case{"inflow-outflow channel", false, false, 0.0, true}}) {
    for (const double dt : {0.002, 0.008}) {
      const double tau = 0.005;
      const Grid g(48, 40, 1.0, 0.8, c.px, c.py);
      FluidBoundaries bc;
      if (!c.py) bc.top.speed = c.lid;
      if (c.channel) {
        bc.left.kind = SideKind::inflow;
        bc.left.inflow.shape = InflowProfile::Shape::parabolic;
        bc.left.inflow.velocity = 1.0;
        bc.right.kind = SideKind::outflow;
      }
      FluidSolver solver(g, 0.01, bc, FluidSchemes{.interpolation_time = tau});
      FluidState s = solver.make_state();
      randomise(g, s, 42);
      solver.initialise_faces(s);
      for (int step = 0; step < 5; ++step) {
        solver.predict_momentum(s, dt, nullptr, nullptr);
        solver.velocity_star_x()(10, 10) += 0.3;
        const ProjectionStats stats = solver.project_smac(s, dt);
        const double ratio = stats.max_divergence_after / stats.max_divergence_before;
        BOOST_TEST_MESSAGE(c.name << ", dt " << dt << ", step " << step << ": max|DU^{n+1}|/max|DU*| = " << ratio);
        BOOST_TEST(ratio < 1e-12);
        // U_f - M u = -tau (I - M A) G_f p on the x-faces two cells from any side.
        const double h = g.dx();
        double defect = 0.0, size = 0.0;
        for (int j = 0; j < g.ny; ++j)
          for (int i = 2; i <= g.nx - 2; ++i) {
            const auto gf = [&](int k) { return (s.pressure(k, j) - s.pressure(k - 1, j)) / h; };
            const double b = gf(i) - 0.25 * (gf(i - 1) + 2.0 * gf(i) + gf(i + 1));
            const double d = s.velocity_face_x(i, j) - 0.5 * (s.velocity_x(i - 1, j) + s.velocity_x(i, j));
            defect = std::max(defect, std::abs(d + tau * b));
            size = std::max(size, std::abs(d));
          }
        BOOST_TEST_MESSAGE("  max|U_f - M u| = " << size << ", defect of -tau (I - M A) G_f p: " << defect);
        BOOST_TEST(defect < 1e-12 * std::max(1.0, size));
      }
    }
  }
}
