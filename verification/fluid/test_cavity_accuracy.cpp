// Accuracy per cell of the lid-driven cavity at Re 1000 against the spectral extrema of Botella &
// Peyret (1998): the largest error of u_min (x = 1/2), v_max and v_min (y = 1/2), each
// the extremum of the cubic spline through the profile located by Brent's method
// (metrics::centreline_extrema; docs/fluid-accuracy.md also gives the figures of the parabola
// through the discrete extremum and its neighbours), run to the case's steady criterion at 64^2. Measured with the spline rule:
// central + linear wall closure (the default) 2.877e-2, QUICK 2.079e-2, quadratic wall closure
// 2.255e-2, both 1.506e-2 (parabola rule, docs/fluid-accuracy.md: 2.81e-2, 2.01e-2, 2.19e-2,
// 1.44e-2; Basilisk, parabola rule: 1.54e-2). Asserted: each option lowers the error by at least
// 15 %, both together by at least 40 % and below Basilisk's 64^2 figure; the default stays within
// 5 % of its measured 2.877e-2 (a change of the default scheme must update this test and the
// documented table).
// Checks docs/method.md §2.2: QUICK convection and the quadratic wall closure together cut the
// Re 1000 cavity's error against Botella & Peyret by at least 40 %, and Fromm with the quadratic
// closure cuts QUICK's by 40 % more.
#define BOOST_TEST_MODULE cavity_accuracy
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "scene/scene_reader.hpp"
#include "metrics/profile.hpp"
#include "sim/run/centreline_profiles.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

using namespace ibms;

namespace {

struct Extrema {
  double value[3];  // u_min, v_max, v_min
  double error;     // largest |value - Botella & Peyret|
};

Extrema botella_peyret_extrema(const std::vector<std::string>& options) {
  std::vector<std::string> sets{"domain.cells_x=64", "domain.cells_y=64"};
  sets.insert(sets.end(), options.begin(), options.end());
  Simulation sim(read_scene_file(IBMS_CAVITY_RE1000_SCENE, sets));
  const double tolerance = sim.scene().run.steady_tolerance;
  VelocityScan scan = scan_velocity(sim.grid(), sim.fluid());
  for (long n = 0; n < 200000; ++n) {
    const double dt = next_time_step(sim, scan);
    advance_one_step(sim, dt);
    scan = scan_velocity(sim.grid(), sim.fluid());
    const ProjectionStats& ps = sim.stats().last_projection;
    if (ps.max_velocity > 0 && ps.max_velocity_change / (dt * ps.max_velocity) < tolerance) break;
  }
  const CentrelineProfiles p = centreline_profiles(sim);
  const std::array<double, 3> measured = centreline_extrema(p.y, p.u, p.x, p.v);
  const double worst = largest_extremum_error(measured, published_extrema(IBMS_BOTELLA_PEYRET));
  std::string label = "default";
  if (!options.empty()) {
    label.clear();
    for (const std::string& o : options) label += o + " ";
  }
  BOOST_TEST_MESSAGE("64^2 " << label << ": u_min " << measured[0] << ", v_max " << measured[1] << ", v_min "
                             << measured[2] << ", largest error " << worst);
  return {{measured[0], measured[1], measured[2]}, worst};
}

double botella_peyret_error(const std::vector<std::string>& options) { return botella_peyret_extrema(options).error; }

}  // namespace

BOOST_AUTO_TEST_CASE(quick_convection_and_quadratic_wall_closure_bring_the_re1000_cavity_closer_to_the_spectral_values) {
  const double central = botella_peyret_error({"fluid.convection=central", "fluid.wall_closure=linear"});
  const double quick = botella_peyret_error({"fluid.convection=quick", "fluid.wall_closure=linear"});
  const double wall = botella_peyret_error({"fluid.convection=central", "fluid.wall_closure=quadratic"});
  const double both = botella_peyret_error({"fluid.convection=quick", "fluid.wall_closure=quadratic"});
  BOOST_TEST(std::abs(central / 2.877e-2 - 1.0) <= 0.05);
  BOOST_TEST(quick <= 0.85 * central);
  BOOST_TEST(wall <= 0.85 * central);
  BOOST_TEST(both <= 0.60 * central);
  BOOST_TEST(both <= 1.54e-2);  // Basilisk at 64^2 (docs/fluid-accuracy.md)
}

// Fromm's face values with the quadratic closure, the scheme of the cavity scenes: measured
// 7.365e-3 with the spline rule, about half the QUICK + quadratic figure. Asserted: at most
// 0.6 of it, below Basilisk's 64^2 figure of the work-precision comparison (1.23e-2,
// bench/reference/basilisk_cavity.csv), and the scene without keys is this scheme (within 5 % of
// the measured figure: a change of the scenes' scheme must update this test and the documented
// tables).
BOOST_AUTO_TEST_CASE(fromm_convection_with_the_quadratic_closure_is_the_scenes_scheme_and_halves_the_quick_error) {
  const double fromm = botella_peyret_error({"fluid.convection=fromm", "fluid.wall_closure=quadratic"});
  const double quick = botella_peyret_error({"fluid.convection=quick", "fluid.wall_closure=quadratic"});
  const double scene = botella_peyret_error({});
  BOOST_TEST(fromm <= 0.60 * quick);
  BOOST_TEST(fromm <= 1.23e-2);
  BOOST_TEST(std::abs(scene / 7.365e-3 - 1.0) <= 0.05);
}

// The cases' steady criterion (run.steady_tolerance = 1e-5: max|u^{n+1} - u^n| /
// (dt max|u|), the largest velocity change per unit time relative to the largest velocity) does
// not limit the accuracy: tightened tenfold, the extrema move by less than 1 % of their error.
BOOST_AUTO_TEST_CASE(the_steady_criterion_does_not_limit_the_cavity_accuracy) {
  const Extrema standard = botella_peyret_extrema({});
  const Extrema tight = botella_peyret_extrema({"run.steady_tolerance=1e-6"});
  double change = 0.0;
  for (int q = 0; q < 3; ++q) change = std::max(change, std::abs(tight.value[q] - standard.value[q]));
  BOOST_TEST_MESSAGE("extrema change with the tolerance / 10: " << change << " (error " << standard.error << ")");
  BOOST_TEST(change < 0.01 * standard.error);
}
