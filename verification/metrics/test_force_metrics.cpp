// The periodic force figures (metrics/force_metrics.hpp) on synthetic histories: the Strouhal number of
// c_L = sin(2 pi f t) is f D / U, also when every step carries a jitter that crosses zero near the
// lift's zero crossings (a coupling that corrects every other step leaves one of 5 % of the
// amplitude); max c_D and max c_L are the maxima over the window.
#define BOOST_TEST_MODULE force_metrics
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "metrics/force_metrics.hpp"

namespace {

struct History {
  std::vector<double> time, drag, lift;
};

// 8 time units from t = 4 at dt = 1e-3; c_L = sin(2 pi f t + 0.3) + jitter (-1)^k, c_D = 3.23 + 0.01 cos(4 pi f t).
History history(double f, double jitter) {
  History h;
  for (int k = 0; k <= 8000; ++k) {
    const double t = 4.0 + 1e-3 * k;
    h.time.push_back(t);
    h.drag.push_back(3.23 + 0.01 * std::cos(4 * ibms::pi * f * t));
    h.lift.push_back(std::sin(2 * ibms::pi * f * t + 0.3) + (k % 2 == 0 ? jitter : -jitter));
  }
  return h;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_strouhal_number_of_a_clean_sine_is_exact) {
  const History h = history(3.0, 0.0);
  const ibms::PeriodicForces p = ibms::periodic_forces(h.time, h.drag, h.lift, {}, 8.0, 0.1, 1.0);
  BOOST_TEST(std::abs(p.strouhal - 0.3) <= 1e-5);
  BOOST_TEST(p.periods == 11);
  BOOST_TEST(std::abs(p.drag_max - 3.24) <= 1e-6);
}

BOOST_AUTO_TEST_CASE(a_step_to_step_jitter_near_zero_does_not_count_as_a_period) {
  const History h = history(3.0, 0.05);
  const ibms::PeriodicForces p = ibms::periodic_forces(h.time, h.drag, h.lift, {}, 8.0, 0.1, 1.0);
  BOOST_TEST_MESSAGE("St with a 5 % jitter: " << p.strouhal << " over " << p.periods << " periods");
  BOOST_TEST(std::abs(p.strouhal - 0.3) <= 3e-4);
  BOOST_TEST(p.periods == 11);
}
