// A swelling disk at rest in quiescent fluid without gravity (docs/method.md §1.8, §8 item 6).
// With the forcing target U_target = U_l - (s'/s)(X_l - X_c) the fluid is forced only by what the
// wheel's motion departs from a uniform dilation: a perfectly homothetic swelling has target 0 and
// leaves the fluid at rest exactly. The direct forcing drives the fluid near the markers towards the
// target, so the flow it induces is bounded by the largest target speed seen over the run,
//   max |u| <= max_n max_l |U_target_l^n|,
// The residual is the wheel's lag behind the schedule: at the kinks of D(t) (onset, end) its breathing
// mode (period ~ 2 dt for k = 1e4 here) is kicked and rings down over a few steps; in between the wheel
// follows the schedule quasi-statically. Measured (logged): target residual 0.57 D'/2 at most, induced
// flow 0.13 D'/2 at most. The pressure equation stays compatible: no source is spread, so the Poisson right-hand
// side has zero mean and the removed mean is round-off.
#define BOOST_TEST_MODULE quiescent_swelling
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "sim_scenes.hpp"

using namespace ibms;

BOOST_AUTO_TEST_CASE(swelling_disk_in_quiescent_fluid_induces_only_the_target_residual_flow) {
  Scene scene = test::one_body_scene(/*n=*/64, /*periodic=*/false, /*diameter=*/0.25, /*density=*/1.25,
                                     /*stiffness=*/1e4);
  scene.fluid.kinematic_viscosity = 0.1;
  const double rate = 0.5;  // dD/dt: swelling from t = 0.02 to 0.12, D 0.25 -> 0.30
  scene.bodies[0].swelling = {true, /*onset_time=*/0.02, rate, /*max_diameter=*/0.30};
  Simulation sim(scene);
  const double dt = 1e-3;   // marker travel D'/2 dt = 2.5e-4 = 0.016 h
  double max_fluid = 0.0, max_target = 0.0, max_removed_mean = 0.0, max_rhs_scale = 0.0;
  for (int n = 0; n < 200; ++n) {
    advance_one_step(sim, dt);
    for (const Vec2& u : sim.markers()[0].target_velocity) max_target = std::max(max_target, std::hypot(u[0], u[1]));
    const Grid& g = sim.grid();
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        max_fluid = std::max(max_fluid, std::hypot(sim.fluid().velocity_x(i, j), sim.fluid().velocity_y(i, j)));
    max_removed_mean = std::max(max_removed_mean, std::abs(sim.stats().last_projection.removed_mean));
    max_rhs_scale = std::max(max_rhs_scale, sim.stats().last_projection.max_divergence_before / dt);
  }
  const double swelling_speed = 0.5 * rate;  // rim speed of the uniform dilation D'/2
  BOOST_TEST_MESSAGE("final D = " << sim.bodies()[0].diameter << ", swelling rim speed D'/2 = " << swelling_speed);
  BOOST_TEST_MESSAGE("max induced fluid speed " << max_fluid << " (" << max_fluid / swelling_speed << " D'/2)");
  BOOST_TEST_MESSAGE("max target speed        " << max_target << " (" << max_target / swelling_speed << " D'/2)");
  BOOST_TEST_MESSAGE("max |removed mean| " << max_removed_mean << " vs max |D U*|/dt " << max_rhs_scale);
  BOOST_TEST(std::abs(sim.bodies()[0].diameter - 0.30) < 1e-12);
  // The bound the §1.8 target allows (see the file comment).
  BOOST_TEST(max_fluid <= max_target);
  // Round-off of a cell sum of 64^2 terms of size max|D U*|/dt.
  BOOST_TEST(max_removed_mean <= 1e-12 * std::max(max_rhs_scale, 1.0));
}
