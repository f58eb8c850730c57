// The fluid solver on a manufactured solution (docs/method.md §A10b): the one runner of the
// convergence tests (verification/fluid/test_manufactured_solution.cpp, test_channel_convergence.cpp)
// and the work-precision benchmark (bench/bench_work_precision.cpp), so that the benchmark times
// the run the tests check. Header-only: the solutions are header-only structs beside the tests
// (fluid/manufactured_solution.hpp, fluid/channel_solution.hpp), and the runner needs the fluid
// module, which solver/metrics (core only) may not use.
// A Solution gives u, v, p, force_x and force_y at (x, y, t) and its viscosity.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/fields.hpp"
#include "core/grid.hpp"
#include "fluid/fluid_solver.hpp"

namespace ibms::verification {

// From the exact field (u, v at t = 0; p at t = -dt/2, where the incremental projection's pressure
// lies) to end_time with the fixed step dt, the forcing evaluated at t^{n+1/2}; with
// steady_tolerance > 0, stops early once max |u^{n+1} - u^n| / (dt max |u|) is below it.
// Returns the steps taken.
template <class Solution>
long run_manufactured(const Solution& ms, const Grid& g, FluidSolver& solver, FluidState& state, double dt,
                      double end_time, double steady_tolerance) {
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      state.velocity_x(i, j) = ms.u(g.x_centre(i), g.y_centre(j), 0.0);
      state.velocity_y(i, j) = ms.v(g.x_centre(i), g.y_centre(j), 0.0);
      state.pressure(i, j) = ms.p(g.x_centre(i), g.y_centre(j), -0.5 * dt);
    }
  solver.initialise_faces(state);
  CellField fx(g), fy(g);
  const long n_steps = std::lround(end_time / dt);
  long steps = 0;
  for (long s = 0; s < n_steps; ++s) {
    const double t_half = state.time + 0.5 * dt;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        fx(i, j) = ms.force_x(g.x_centre(i), g.y_centre(j), t_half);
        fy(i, j) = ms.force_y(g.x_centre(i), g.y_centre(j), t_half);
      }
    solver.predict_momentum(state, dt, &fx, &fy);
    const ProjectionStats stats = solver.project_smac(state, dt);
    ++steps;
    if (steady_tolerance > 0 && stats.max_velocity_change / (dt * stats.max_velocity) < steady_tolerance) break;
  }
  return steps;
}

// L2 (root mean square over the cells) and max norms of the errors of u, v and p.
struct ManufacturedErrors {
  double u_l2 = 0, u_max = 0, v_l2 = 0, v_max = 0, p_l2 = 0, p_max = 0;
};

// The errors of `state` against the exact field at its time t; the pressure p^{n+1} approximates
// p(t^{n+1/2}) (incremental projection, Brown, Cortez & Minion 2001), so it is compared at t - dt/2.
// remove_pressure_mean: compare after removing the mean of the computed pressure (walls all round
// fix p only up to a constant; the exact one has zero mean).
template <class Solution>
ManufacturedErrors manufactured_errors(const Solution& ms, const Grid& g, const FluidState& state, double dt,
                                       bool remove_pressure_mean) {
  const double t = state.time, t_p = t - 0.5 * dt;
  const int cells = g.nx * g.ny;
  double mean_p = 0;
  if (remove_pressure_mean) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) mean_p += state.pressure(i, j);
    mean_p /= cells;
  }
  ManufacturedErrors e;
  double su = 0, sv = 0, sp = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.x_centre(i), y = g.y_centre(j);
      const double eu = std::abs(state.velocity_x(i, j) - ms.u(x, y, t));
      const double ev = std::abs(state.velocity_y(i, j) - ms.v(x, y, t));
      const double ep = std::abs(state.pressure(i, j) - mean_p - ms.p(x, y, t_p));
      su += eu * eu; sv += ev * ev; sp += ep * ep;
      // fmax with a NaN error would hide a blow-up: make it infinite instead.
      e.u_max = std::max(e.u_max, std::isfinite(eu) ? eu : HUGE_VAL);
      e.v_max = std::max(e.v_max, std::isfinite(ev) ? ev : HUGE_VAL);
      e.p_max = std::max(e.p_max, std::isfinite(ep) ? ep : HUGE_VAL);
    }
  e.u_l2 = std::sqrt(su / cells);
  e.v_l2 = std::sqrt(sv / cells);
  e.p_l2 = std::sqrt(sp / cells);
  return e;
}

}  // namespace ibms::verification
