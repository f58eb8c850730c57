// The end of a run does not move the body forces (docs/method.md §7, "The approach to
// run.end_time"). A step that differs from its predecessor by a fraction x makes the no_slip
// coupling's force spike by about x times the momentum interpolation's face term, so a run that
// lands on end_time with a short last step reports a force its longer twin never sees. Here a fixed
// cylinder in a channel at Re 12.5 (adaptive step, CFL 0.5; the face-constrained no_slip coupling
// solved to a slip of 1e-8, so that its tolerance does not blur the comparison, and the papers'
// coupling) runs to end times placed at several fractions of a step past t = 2; over its last 110
// steps every drag and lift agrees with a run to t = 2.3 (interpolated to the same times) within
// 0.5 % of the drag, and no step differs from the one before by more than 1.1 % (the plan's
// 1 / 100). The previous rule (a 5 % cut about 105 steps before the end) fails both checks for the
// papers' coupling (2.2 % of the drag), whose force depends on the step.
#define BOOST_TEST_MODULE end_of_run_forces
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fluid/threads.hpp"
#include "scene/scene_reader.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

namespace {

struct Record {
  std::vector<double> time, dt, drag, lift;
};

Record run_to(const std::string& coupling, double end_time) {
  ibms::set_thread_count(1);
  char end[64];
  std::snprintf(end, sizeof end, "run.end_time=%.17g", end_time);
  const ibms::Scene scene = ibms::read_scene_file(
      IBMS_CYLINDER_SCENE,
      {"run.time_step=0", "run.cfl=0.5", end, "ibm.coupling=\"" + coupling + "\"", "ibm.constrained_velocity=\"faces\"",
       "ibm.slip_tolerance=1e-8"});
  ibms::Simulation sim(scene);
  Record r;
  ibms::VelocityScan scan = ibms::scan_velocity(sim.grid(), sim.fluid());
  BOOST_REQUIRE(scene.run.end_time == end_time);
  while (sim.fluid().time < end_time - 1e-12) {
    const double dt = ibms::next_time_step(sim, scan);
    ibms::advance_one_step(sim, dt);
    scan = ibms::scan_velocity(sim.grid(), sim.fluid());
    r.time.push_back(sim.fluid().time);
    r.dt.push_back(dt);
    r.drag.push_back(sim.markers()[0].hydrodynamic_force[0]);
    r.lift.push_back(sim.markers()[0].hydrodynamic_force[1]);
  }
  return r;
}

double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at) {
  const auto it = std::lower_bound(t.begin(), t.end(), at);
  const std::size_t k = std::clamp<std::size_t>(it - t.begin(), 1, t.size() - 1);
  const double w = (at - t[k - 1]) / (t[k] - t[k - 1]);
  return (1 - w) * y[k - 1] + w * y[k];
}

void check_coupling(const std::string& coupling) {
  const Record reference = run_to(coupling, 2.3);
  const auto near = std::lower_bound(reference.time.begin(), reference.time.end(), 2.0);
  const double dt = reference.dt[near - reference.time.begin()];
  for (const double fraction : {0.05, 0.3, 0.55, 0.8}) {
    const double end_time = 2.0 + fraction * dt;
    const Record r = run_to(coupling, end_time);
    BOOST_REQUIRE(r.time.size() > 110u);
    BOOST_TEST(std::abs(r.time.back() - end_time) <= 1e-12);
    double largest_force = 0.0, largest_step = 0.0;
    for (std::size_t k = r.time.size() - 110; k < r.time.size(); ++k) {
      const double drag = interpolate(reference.time, reference.drag, r.time[k]);
      const double lift = interpolate(reference.time, reference.lift, r.time[k]);
      largest_force = std::max({largest_force, std::abs(r.drag[k] - drag) / std::abs(drag),
                                std::abs(r.lift[k] - lift) / std::abs(drag)});
      largest_step = std::max(largest_step, std::abs(r.dt[k] / r.dt[k - 1] - 1.0));
    }
    BOOST_TEST_MESSAGE(coupling << ", end " << end_time << ": largest force change " << largest_force
                                << " of the drag, largest step change " << largest_step);
    BOOST_TEST(largest_force <= 0.005);
    BOOST_TEST(largest_step <= 0.011);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(no_slip_forces_do_not_see_the_end) { check_coupling("no_slip"); }

BOOST_AUTO_TEST_CASE(uhlmann_forces_do_not_see_the_end) { check_coupling("uhlmann"); }
