// The adaptive step sees where a prescribed body is going (docs/method.md §7, "The approach to run.end_time"): the marker
// travel limit takes the body's largest speed over the coming step from its motion law, so a body
// that starts at rest in fluid at rest is not run as one step of the whole end_time; it plans the
// same number of steps per period as one that starts at its peak speed, `ibms info`'s first step
// (planned_time_step) is the run's, and no step carries a marker further than 0.5 h (beyond the
// approach to end_time's 5 %).
#define BOOST_TEST_MODULE prescribed_time_step
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/constants.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "sim/time_step_limits.hpp"
#include "solid/rigid_motion.hpp"

using namespace ibms;

namespace {

constexpr double amplitude = 0.0625;  // A = 4 h at 64^2 [length]
constexpr double period = 1.0;        // T [time]

// A prescribed cylinder (D = 0.25) oscillating along x as x_c = 0.5 + A sin(2 pi t / T + phase)
// in a closed unit box of fluid at rest, 64^2 cells, the papers' coupling.
Scene oscillating_cylinder(double phase) {
  Scene scene;
  scene.source_file = "(test scene)";
  scene.domain = {1.0, 1.0, 64, 64, false, false};
  scene.fluid.density = 1.0;
  scene.fluid.kinematic_viscosity = 0.01;
  scene.run.end_time = 2.0 * period;
  scene.run.cfl = 0.5;
  BodySpec body;
  body.kind = BodySpec::Kind::prescribed;
  body.centre = {0.5, 0.5};
  body.diameter = 0.25;
  body.n_surface_points = 48;
  body.density = 1.0;
  body.oscillation_amplitude = {amplitude, 0.0};
  body.oscillation_period = period;
  body.oscillation_phase = phase;
  scene.bodies.push_back(body);
  return scene;
}

struct Steps {
  double first = 0.0;       // the run's first step
  double planned = 0.0;     // planned_time_step before it (what `ibms info` prints)
  long count = 0;
  double max_travel = 0.0;  // largest dt max_[t, t + dt] |U| / h over the steps [-]
  double max_fluid_speed = 0.0;
};

// Steps the scene as run_simulation does, with the adaptive step.
Steps run(const Scene& scene) {
  Simulation sim(scene);
  Steps out;
  out.planned = planned_time_step(sim);
  const RigidBody& rigid = sim.rigid()[0];
  const double h = sim.grid().dx();
  while (sim.fluid().time < scene.run.end_time - 1e-12) {
    const double t = sim.fluid().time;
    const double dt = next_time_step(sim, scan_velocity(sim.grid(), sim.fluid()));
    if (out.count == 0) out.first = dt;
    // The largest speed over the step, sampled densely from the motion law.
    double speed = 0.0;
    for (int k = 0; k <= 200; ++k) {
      const RigidState s = rigid.prescribed.at(t + dt * k / 200.0);
      speed = std::max(speed, std::hypot(s.velocity[0], s.velocity[1]));
    }
    out.max_travel = std::max(out.max_travel, dt * speed / h);
    advance_one_step(sim, dt);
    ++out.count;
  }
  out.max_fluid_speed = scan_velocity(sim.grid(), sim.fluid()).max_speed;
  return out;
}

}  // namespace

// The bound of the motion law over an interval against dense sampling: never below it, and equal
// to it (within the sampling's error) for a translating body.
BOOST_AUTO_TEST_CASE(largest_speed_over_an_interval_bounds_the_motion) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double worst_gap = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    PrescribedMotion m;
    m.velocity = {0.3 * uniform(random), 0.3 * uniform(random)};
    m.amplitude = {uniform(random), uniform(random)};
    m.period = 1.0 + 0.5 * uniform(random);
    m.phase = 3.0 * uniform(random);
    const bool rotates = trial % 2 == 1;
    if (rotates) { m.angular_velocity = uniform(random); m.angle_amplitude = uniform(random); }
    const double radius = 0.2;
    const double t0 = 2.0 * uniform(random), t1 = t0 + 0.6 * (1.0 + uniform(random));
    double sampled = 0.0;
    for (int k = 0; k <= 20000; ++k) {
      const RigidState s = m.at(t0 + (t1 - t0) * k / 20000.0);
      const double centre = std::hypot(s.velocity[0], s.velocity[1]);
      sampled = std::max(sampled, centre + radius * std::abs(s.angular_velocity));
    }
    const double bound = m.max_point_speed(t0, t1, radius);
    BOOST_TEST(bound >= sampled * (1.0 - 1e-12));
    if (!rotates) worst_gap = std::max(worst_gap, (bound - sampled) / sampled);
  }
  BOOST_TEST_MESSAGE("translating bodies: the bound exceeds the sampled maximum by at most " << worst_gap);
  BOOST_TEST(worst_gap < 1e-6);
}

BOOST_AUTO_TEST_CASE(a_body_that_starts_at_rest_plans_the_steps_of_one_that_starts_moving) {
  const Steps at_rest = run(oscillating_cylinder(0.5 * pi));  // U(0) = 0
  const Steps moving = run(oscillating_cylinder(0.0));        // U(0) = A w, the peak
  BOOST_TEST_MESSAGE("from rest: " << at_rest.count << " steps, first " << at_rest.first << ", travel <= "
                                   << at_rest.max_travel << " h; from the peak: " << moving.count << " steps, first "
                                   << moving.first << ", travel <= " << moving.max_travel << " h");
  // The travel over a period is 4 A = 16 h: at most 0.5 h a step, about 32 steps a period.
  BOOST_TEST(at_rest.count >= 2 * 32);
  BOOST_TEST(std::abs(at_rest.count - moving.count) <= 0.1 * moving.count);
  // Within 100 steps of end_time (all of this run) the step may stay up to end_overshoot above
  // its limits rather than jump (docs/method.md §7, "The approach to run.end_time").
  BOOST_TEST(at_rest.max_travel <= max_marker_travel_cells * (1.0 + end_overshoot));
  BOOST_TEST(moving.max_travel <= max_marker_travel_cells * (1.0 + end_overshoot));
  BOOST_TEST(at_rest.first == at_rest.planned);  // `ibms info` prints the run's first step
  BOOST_TEST(moving.first == moving.planned);
  BOOST_TEST(at_rest.max_fluid_speed > 0.1 * amplitude * 2.0 * pi / period);  // the body has moved the fluid
}
