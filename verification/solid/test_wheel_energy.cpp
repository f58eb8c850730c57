// An undamped wheel (N_l = 20, k = 1e3) released from an elliptic deformation, integrated with
// symplectic Euler (docs/method.md §5.1) for 1000 periods T = 2 pi sqrt(M/k): the energy error is
// bounded (no drift) and first order in the sub-step. Why first order: symplectic Euler exactly
// conserves a modified energy H~ = H + O(dt) (backward error analysis, Hairer, Lubich & Wanner
// 2006, ch. IX; for one mode H~ = H - (dt/2) omega^2 x v), so |H - H0|/H0 stays bounded but is
// O(omega dt), not O(dt^2).
// With IBMS_RESULTS_DIR set (ctest), the table goes to wheel_energy.csv and the error history (its
// maximum over each period, one row per period and sub-step) to wheel_energy_history.csv for the
// report (verification/common/results_csv.hpp).
#define BOOST_TEST_MODULE wheel_energy
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../common/results_csv.hpp"
#include "core/constants.hpp"

#include "solid/mass_spring_body.hpp"
#include "solid/spring_forces.hpp"
#include "solid/stable_substep.hpp"
#include "solid/symplectic_euler.hpp"

using namespace ibms;

namespace {

MassSpringBody deformed_wheel() {
  BodyParameters spec;
  spec.centre = {0.3, -0.2};
  spec.diameter = 1.0;
  spec.n_surface_points = 20;
  spec.density = 1.0;
  spec.spring_stiffness = 1e3;
  spec.spring_damping = 0.0;  // undamped
  MassSpringBody body = build_wheel(spec);
  // Elliptic deformation of the rim (+5 % in x, -5 % in y) and an off-centre hub.
  for (int l = 0; l < body.n_surface; ++l) {
    body.position[l][0] = 0.3 + 1.05*(body.position[l][0] - 0.3);
    body.position[l][1] = -0.2 + (body.position[l][1] + 0.2)/1.05;
  }
  body.position[body.centre_index()][0] += 0.02;
  return body;
}

double total_energy(const MassSpringBody& body) {
  return kinetic_energy(body) + spring_energy(body, body.length_scale());
}

struct EnergyRun {
  double max_error, first_window, last_window;
  std::vector<double> period_max;  // max relative error over each period (the report's history)
};

// Relative energy error over n_periods; max over all, the first and the last 100 periods.
EnergyRun run(double dt, double period, int n_periods) {
  MassSpringBody body = deformed_wheel();
  const double e0 = total_energy(body);
  const std::vector<std::array<double, 2>> no_force(body.n_points(), {0.0, 0.0});
  const long n_steps = std::lround(n_periods * period / dt);
  const long window = std::lround(100 * period / dt);
  EnergyRun r{0, 0, 0, std::vector<double>(n_periods, 0.0)};
  for (long n = 1; n <= n_steps; ++n) {
    advance_symplectic_euler(body, dt, no_force);
    const double error = std::abs(total_energy(body) - e0) / e0;
    r.max_error = std::max(r.max_error, error);
    const long p = std::min<long>(n_periods - 1, static_cast<long>((n - 0.5) * dt / period));
    r.period_max[p] = std::max(r.period_max[p], error);
    if (n <= window) r.first_window = std::max(r.first_window, error);
    if (n > n_steps - window) r.last_window = std::max(r.last_window, error);
  }
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(undamped_wheel_energy_error_is_bounded_and_first_order) {
  const MassSpringBody body = deformed_wheel();
  const double period = 2.0*pi*std::sqrt(body.mass[0] / 1e3);
  const double omega_bound = std::sqrt(spectral_bounds(body).omega_squared_max);
  const double dt0 = stable_substep(body, /*safety=*/0.25);
  BOOST_TEST_MESSAGE("T = " << period << ", omega_max bound = " << omega_bound);
  BOOST_TEST_MESSAGE("dt    steps/T    omega_max dt    max rel energy error    first 100 T    last 100 T    order");
  std::vector<EnergyRun> runs;
  std::vector<std::string> table, history;  // CSV rows for the report
  using verification::csv_number;
  for (int level = 0; level < 3; ++level) {
    const double dt = dt0 / (1 << level);
    runs.push_back(run(dt, period, /*n_periods=*/1000));
    const EnergyRun& r = runs.back();
    const double order = level == 0 ? 0.0 : std::log2(runs[level - 1].max_error / r.max_error);
    BOOST_TEST_MESSAGE(dt << "    " << period/dt << "    " << omega_bound*dt << "    " << r.max_error
                       << "    " << r.first_window << "    " << r.last_window << "    " << order);
    // Bounded: for one mode |H - H~| <= (omega dt/2) H, so |H/H0 - 1| <= omega dt/(1 - omega dt/2).
    const double w = omega_bound * dt;
    BOOST_TEST(r.max_error <= w / (1.0 - 0.5*w));
    // No drift: a secular error would grow ~10x from the first to the last 100 of 1000 periods;
    // the bounded, quasi-periodic error of a symplectic method changes its window maximum only
    // through the beating of the excited modes, allowed here to 20 %.
    BOOST_TEST(r.last_window <= 1.2 * r.first_window);
    // First order (see the file header), with 0.1 allowance for the pre-asymptotic range.
    if (level > 0) BOOST_TEST(order >= 0.9);
    table.push_back(csv_number(dt) + "," + csv_number(period/dt) + "," + csv_number(w) + "," +
                    csv_number(r.max_error) + "," + csv_number(r.first_window) + "," +
                    csv_number(r.last_window) + "," + csv_number(w / (1.0 - 0.5*w)) + "," +
                    (level == 0 ? std::string() : csv_number(order)));
    for (std::size_t p = 0; p < r.period_max.size(); ++p)
      history.push_back(csv_number(dt) + "," + csv_number(static_cast<double>(p + 1)) + "," +
                        csv_number(r.period_max[p]));
  }
  // Order empty on the coarsest sub-step: a rerun's rows start a new table there.
  verification::append_results_csv(
      "wheel_energy.csv",
      "dt,steps_per_period,omega_max_dt,max_rel_error,first_100T_max,last_100T_max,bound,order", table);
  verification::append_results_csv("wheel_energy_history.csv",
                                   "dt,periods,max_rel_error_over_period", history);
}
