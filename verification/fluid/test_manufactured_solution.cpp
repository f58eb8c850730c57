// Claims (docs/method.md §A10b, §2.4): with no-slip walls the collocated SMAC solver is second
// order in space for u, v and p in L2 and max norms (>= 1.9 over four grids), and second order in
// time for the velocity (>= 1.8) on a fixed fine grid; the pressure at least first order in time.
#define BOOST_TEST_MODULE manufactured_solution
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "../common/convergence.hpp"
#include "../common/manufactured_run.hpp"
#include "fluid/fluid_solver.hpp"
#include "manufactured_solution.hpp"

using namespace ibms;
using verification::ManufacturedSolution;

namespace {

struct Run {
  FluidState state;
  verification::ManufacturedErrors errors;
  long steps = 0;
};

// Runs the solver from the exact initial field to `end_time` (or to steady state when
// steady_tolerance > 0) with a fixed dt (common/manufactured_run.hpp); the errors with the
// pressure's mean removed.
Run run(const ManufacturedSolution& ms, int n, double dt, double end_time, double steady_tolerance,
        FluidSchemes schemes = {}) {
  const Grid g(n, n, 1.0, 1.0);
  FluidSolver solver(g, ms.viscosity, FluidBoundaries{}, schemes);
  Run r{solver.make_state(), {}, 0};
  r.steps = verification::run_manufactured(ms, g, solver, r.state, dt, end_time, steady_tolerance);
  r.errors = verification::manufactured_errors(ms, g, r.state, dt, /*remove_pressure_mean=*/true);
  return r;
}

// Prints the table for one norm and checks the finest-three order and that the three lie on one line.
void check_order(const std::string& name, const std::vector<int>& n, const std::vector<double>& e,
                 double required) {
  std::vector<double> h;
  for (int k : n) h.push_back(1.0 / k);
  BOOST_TEST_MESSAGE(verification::convergence_table(name, n, h, e, {2.0, required, 2.0 + verification::max_order_excess, "h"}));
  BOOST_TEST(verification::finest_three_fit(h, e).standard_error <= verification::max_order_standard_error);
  BOOST_TEST(verification::finest_three_slope(h, e) >= required);
  BOOST_TEST(verification::finest_three_slope(h, e) <= 2.0 + verification::max_order_excess);
}

void spatial_study(bool steady, FluidSchemes schemes = {}, std::vector<int> grids = {16, 32, 64, 128}) {
  ManufacturedSolution ms;
  ms.steady = steady;
  std::vector<double> ul2, umax, vl2, vmax, pl2, pmax;
  for (int n : grids) {
    // dt proportional to h (CFL about 0.25 at |u| = 1) so time error shrinks like h^2 too.
    const double dt = 0.25 / n;
    const Run r = steady ? run(ms, n, dt, /*end_time=*/40.0, /*steady_tolerance=*/1e-9, schemes)
                         : run(ms, n, dt, /*end_time=*/1.0, 0.0, schemes);
    BOOST_TEST_MESSAGE("N = " << n << ": " << r.steps << " steps to t = " << r.state.time);
    ul2.push_back(r.errors.u_l2); umax.push_back(r.errors.u_max);
    vl2.push_back(r.errors.v_l2); vmax.push_back(r.errors.v_max);
    pl2.push_back(r.errors.p_l2); pmax.push_back(r.errors.p_max);
  }
  // Velocity and pressure >= 1.9 (formal order 2 minus the 0.1 margin of docs/design.md §6). docs/method.md
  // A10b expects O(h^1.5) for p near walls on a collocated grid; measured 1.94-1.99 in both norms,
  // so the design's rule applies to p as well.
  const std::string kind = std::string(steady ? "steady MMS, " : "unsteady MMS (t = 1), ") +
                           (schemes.convection == ConvectionScheme::central
                                ? std::string()
                                : convection_name(schemes.convection) + std::string(" convection, ")) +
                           (schemes.quadratic_wall ? "quadratic wall closure, " : "");
  check_order(kind + "u, L2 norm", grids, ul2, 1.9);
  check_order(kind + "u, max norm", grids, umax, 1.9);
  check_order(kind + "v, L2 norm", grids, vl2, 1.9);
  check_order(kind + "v, max norm", grids, vmax, 1.9);
  check_order(kind + "p, L2 norm", grids, pl2, 1.9);
  check_order(kind + "p, max norm", grids, pmax, 1.9);
}

}  // namespace

BOOST_AUTO_TEST_CASE(steady_velocity_and_pressure_converge_at_second_order_in_space) {
  spatial_study(/*steady=*/true);
}

BOOST_AUTO_TEST_CASE(unsteady_velocity_and_pressure_converge_at_second_order_in_space) {
  spatial_study(/*steady=*/false);
}

// Fixed 64^2 grid, dt halved four times; the error of each run against the next finer-dt run
// (the spatial error cancels) gives the temporal order. The five runs serve the velocity and the
// pressure study (computed once per test program).
const std::vector<int> time_study_steps{10, 20, 40, 80, 160};

const std::vector<FluidState>& time_study_runs() {
  static const std::vector<FluidState> finals = [] {
    ManufacturedSolution ms;
    ms.steady = false;
    std::vector<FluidState> states;
    for (int s : time_study_steps) states.push_back(run(ms, 64, 1.0 / s, 1.0, 0.0).state);
    return states;
  }();
  return finals;
}

// max over the cells of distance(run k, run k + 1) for each successive pair, as (h = dt, error).
template <class Distance>
void time_differences(Distance distance, std::vector<int>& n, std::vector<double>& h, std::vector<double>& e) {
  const std::vector<FluidState>& finals = time_study_runs();
  for (std::size_t k = 0; k + 1 < finals.size(); ++k) {
    n.push_back(time_study_steps[k]);
    h.push_back(1.0 / time_study_steps[k]);
    e.push_back(distance(finals[k], finals[k + 1]));
  }
}

BOOST_AUTO_TEST_CASE(velocity_is_second_order_in_time) {
  std::vector<double> h, e;
  std::vector<int> n;
  time_differences([](const FluidState& a, const FluidState& b) {
    double err = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i)
        err = std::max({err, std::abs(a.velocity_x(i, j) - b.velocity_x(i, j)),
                        std::abs(a.velocity_y(i, j) - b.velocity_y(i, j))});
    return err;
  }, n, h, e);
  BOOST_TEST_MESSAGE(verification::convergence_table(
      "velocity, max |u_dt - u_dt/2| at t = 1 on 64^2 (N = steps)", n, h, e, {2.0, 1.8, 2.0 + verification::max_order_excess, "dt"}));
  BOOST_TEST(verification::finest_three_fit(h, e).standard_error <= verification::max_order_standard_error);
  BOOST_TEST(verification::finest_three_slope(h, e) >= 1.8);  // the target: formal order 2 less 0.2
  BOOST_TEST(verification::finest_three_slope(h, e) <= 2.0 + verification::max_order_excess);
}

// The same time study for the pressure: max |p_dt - p_dt/2| at t = 1 on 64^2. Expected order 1, not
// 2: ibms uses the standard incremental update p^{n+1} = p^n + phi (README "Departures": the
// rotational form is unstable on this collocated grid), and the standard form's pressure carries a
// numerical boundary layer that limits it to first order in time (Guermond, Minev & Shen 2006,
// Comput. Methods Appl. Mech. Engrg. 195:6011, §3.3). Measured: 1.32 / 1.32 / 1.24 pairwise, slope
// 1.28. Asserted >= 0.9 (expected 1 minus the 0.1 margin of docs/design.md §6).
BOOST_AUTO_TEST_CASE(pressure_is_first_order_in_time) {
  std::vector<double> h, e;
  std::vector<int> n;
  time_differences([](const FluidState& a, const FluidState& b) {
    // Pressure is defined up to a constant: compare after removing each field's mean.
    double mean_a = 0, mean_b = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) {
        mean_a += a.pressure(i, j) / (64.0 * 64.0);
        mean_b += b.pressure(i, j) / (64.0 * 64.0);
      }
    double err = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) err = std::max(err, std::abs((a.pressure(i, j) - mean_a) - (b.pressure(i, j) - mean_b)));
    return err;
  }, n, h, e);
  BOOST_TEST_MESSAGE(verification::convergence_table(
      "pressure, max |p_dt - p_dt/2| at t = 1 on 64^2 (N = steps)", n, h, e, {1.0, 0.9, 1.0 + verification::max_order_excess, "dt"}));
  BOOST_TEST(verification::finest_three_fit(h, e).standard_error <= verification::max_order_standard_error);
  BOOST_TEST(verification::finest_three_slope(h, e) >= 0.9);
  BOOST_TEST(verification::finest_three_slope(h, e) <= 1.0 + verification::max_order_excess);
}

// The spatial options (QUICK convection, quadratic wall closure, fluid_solver.hpp)
// keep the asserted orders: second order in space for u, v, p (>= 1.9, both norms) and in time
// for the velocity (>= 1.8). The errors are about half the default's at 128^2 (u max 1.2e-4
// against 2.4e-4, p max 9.7e-5 against 1.8e-4), but the pressure's max norm approaches its order
// from below (pairwise 1.79, 1.85, 1.92 from 16^2 to 128^2: slope 1.89 over 32-128), so this
// study adds 256^2 and takes the slope over 64-256.
namespace {

// Second order in space (spatial_study over `grids`) and in time for the velocity (>= 1.8, max
// |u_dt - u_dt/2| at t = 1 on 64^2) under `options`, named `label` in the tables.
void options_keep_second_order(const FluidSchemes& options, const std::string& label, const std::vector<int>& grids) {
  spatial_study(/*steady=*/false, options, grids);
  ManufacturedSolution ms;
  ms.steady = false;
  std::vector<FluidState> finals;
  for (int s : time_study_steps) finals.push_back(run(ms, 64, 1.0 / s, 1.0, 0.0, options).state);
  std::vector<double> h, e;
  std::vector<int> n;
  for (std::size_t k = 0; k + 1 < finals.size(); ++k) {
    double err = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i)
        err = std::max({err, std::abs(finals[k].velocity_x(i, j) - finals[k + 1].velocity_x(i, j)),
                        std::abs(finals[k].velocity_y(i, j) - finals[k + 1].velocity_y(i, j))});
    n.push_back(time_study_steps[k]);
    h.push_back(1.0 / time_study_steps[k]);
    e.push_back(err);
  }
  BOOST_TEST_MESSAGE(verification::convergence_table(
      label + ": velocity, max |u_dt - u_dt/2| at t = 1 on 64^2 (N = steps)", n, h, e, {2.0, 1.8, 2.0 + verification::max_order_excess, "dt"}));
  BOOST_TEST(verification::finest_three_slope(h, e) >= 1.8);
  BOOST_TEST(verification::finest_three_slope(h, e) <= 2.0 + verification::max_order_excess);
}

}  // namespace

BOOST_AUTO_TEST_CASE(quick_convection_and_quadratic_wall_closure_keep_second_order) {
  options_keep_second_order({ConvectionScheme::quick, /*quadratic_wall=*/true}, "QUICK + quadratic wall",
                            {16, 32, 64, 128, 256});
}

// Fromm's face values (kappa = 0) with the quadratic closure keep the same orders.
BOOST_AUTO_TEST_CASE(fromm_convection_and_quadratic_wall_closure_keep_second_order) {
  options_keep_second_order({ConvectionScheme::fromm, /*quadratic_wall=*/true}, "Fromm + quadratic wall",
                            {16, 32, 64, 128, 256});
}

// The third-order upwind-biased face values (kappa = 1/3) with the linear closure (the DFG 2D-2
// scene's options) keep the same orders.
BOOST_AUTO_TEST_CASE(upwind3_convection_keeps_second_order) {
  options_keep_second_order({ConvectionScheme::upwind3, /*quadratic_wall=*/false}, "upwind3 + linear wall",
                            {16, 32, 64, 128, 256});
}

// The quadratic closure's single sweep from the explicit estimate (complete_prediction, taken up to
// nu dt / h^2 = FluidSchemes::single_sweep_viscous_number): at nu = 0.004 on 64^2 every step of the
// time study below has nu dt / h^2 <= 0.205, so every step takes it. The velocity stays second
// order in time (>= 1.8, as the swept path above), the runs differ from those of the path that
// sweeps from u^n (FluidSolver::closure_sweeps; the single sweep is taken), and a steady state is
// that path's: both are fixed points of the same discrete equations.
BOOST_AUTO_TEST_CASE(single_sweep_wall_closure_keeps_second_order_in_time_and_the_steady_state) {
  const FluidSchemes single{ConvectionScheme::quick, /*quadratic_wall=*/true};
  FluidSchemes swept = single;
  swept.single_sweep_viscous_number = 0.0;  // always closure_sweeps sweeps from u^n
  ManufacturedSolution ms;
  ms.steady = false;
  ms.viscosity = 0.004;
  const std::vector<int> steps{80, 160, 320, 640};
  std::vector<FluidState> finals;
  for (int s : steps) finals.push_back(run(ms, 64, 1.0 / s, 1.0, 0.0, single).state);
  const auto max_difference = [](const FluidState& a, const FluidState& b) {
    double err = 0;
    for (int j = 0; j < a.velocity_x.ny(); ++j)
      for (int i = 0; i < a.velocity_x.nx(); ++i)
        err = std::max({err, std::abs(a.velocity_x(i, j) - b.velocity_x(i, j)),
                        std::abs(a.velocity_y(i, j) - b.velocity_y(i, j))});
    return err;
  };
  std::vector<double> h, e;
  std::vector<int> n;
  for (std::size_t k = 0; k + 1 < finals.size(); ++k) {
    n.push_back(steps[k]);
    h.push_back(1.0 / steps[k]);
    e.push_back(max_difference(finals[k], finals[k + 1]));
  }
  BOOST_TEST_MESSAGE(verification::convergence_table(
      "QUICK + quadratic wall, one sweep (nu = 0.004): velocity, max |u_dt - u_dt/2| at t = 1 on 64^2 (N = steps)", n,
      h, e, {2.0, 1.8, 2.0 + verification::max_order_excess, "dt"}));
  BOOST_TEST(verification::finest_three_slope(h, e) >= 1.8);
  BOOST_TEST(verification::finest_three_slope(h, e) <= 2.0 + verification::max_order_excess);
  const double path_difference = max_difference(finals[0], run(ms, 64, 1.0 / steps[0], 1.0, 0.0, swept).state);
  BOOST_TEST_MESSAGE("one sweep against the swept path at dt = 1/80: max |u difference| = " << path_difference
                     << " (time error at that dt: " << e[0] << ")");
  BOOST_TEST(path_difference > 1e-12);
  BOOST_TEST(path_difference < e[0]);

  ManufacturedSolution steady;
  steady.steady = true;
  const double dt = 0.002;  // nu dt / h^2 = 0.2048 on 32^2 at nu = 0.1
  const Run a = run(steady, 32, dt, 40.0, 1e-10, single), b = run(steady, 32, dt, 40.0, 1e-10, swept);
  BOOST_TEST_MESSAGE("steady MMS 32^2: one sweep " << a.steps << " steps, swept path " << b.steps
                     << " steps, max |u difference| = " << max_difference(a.state, b.state) << ", u error "
                     << a.errors.u_max);
  BOOST_TEST(max_difference(a.state, b.state) < 1e-3 * a.errors.u_max);
}

// The sweeps from u^n above the single-sweep threshold: the fewest k with rho(d)^k <= (4/9)^3, the
// contraction three sweeps guarantee at any viscous number d (rho(d) = (2/3) d / (1 + (3/2) d) < 4/9):
// 2 up to d = 4/3 (the Re 100 cavity at 128^2 and 256^2: 0.58, 1.15), 3 above.
BOOST_AUTO_TEST_CASE(closure_sweeps_keep_the_contraction_of_three_sweeps_at_any_viscous_number) {
  const double bound = std::pow(4.0 / 9.0, FluidSolver::wall_closure_sweeps);
  for (double d = 0.26; d < 1e4; d *= 1.1) {
    const double rho = (2.0 / 3.0) * d / (1.0 + 1.5 * d);
    const int k = FluidSolver::closure_sweeps(d);
    BOOST_TEST(std::pow(rho, k) <= bound * (1 + 1e-12));
    if (k > 1) BOOST_TEST(std::pow(rho, k - 1) > bound);  // the fewest
    BOOST_TEST(k <= FluidSolver::wall_closure_sweeps);
  }
  BOOST_TEST(FluidSolver::closure_sweeps(0.58) == 2);
  BOOST_TEST(FluidSolver::closure_sweeps(1.15) == 2);
  BOOST_TEST(FluidSolver::closure_sweeps(1.3) == 2);
  BOOST_TEST(FluidSolver::closure_sweeps(1.4) == 3);
}
