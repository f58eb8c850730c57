// The time-step rule of the run (docs/method.md §7): the velocity scan, the speed scales and the next step.
#include "sim/time_step_limits.hpp"

#include <algorithm>
#include <cmath>


namespace ibms {

VelocityScan scan_velocity(const Grid& grid, const FluidState& fluid) {
  VelocityScan scan;
  const double inv_dx = 1.0 / grid.dx(), inv_dy = 1.0 / grid.dy();
  double sum_squares = 0.0, max_square = 0.0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double u = fluid.velocity_x(i, j), v = fluid.velocity_y(i, j);
      const double rate = std::abs(u) * inv_dx + std::abs(v) * inv_dy;
      if (!std::isfinite(rate) || !std::isfinite(fluid.pressure(i, j))) {
        return {HUGE_VAL, i, j, false, HUGE_VAL, i, j, HUGE_VAL};
      }
      if (rate > scan.max_rate) { scan.max_rate = rate; scan.i = i; scan.j = j; }
      const double square = u*u + v*v;
      sum_squares += square;
      if (square > max_square) { max_square = square; scan.speed_i = i; scan.speed_j = j; }
    }
  scan.max_speed = std::sqrt(max_square);
  scan.kinetic_energy = 0.5 * sum_squares * grid.cell_area();
  return scan;
}

// The approach to end_time (docs/method.md §7, "The approach to run.end_time"). A step that differs from its predecessor by a
// fraction x makes the body forces spike by about x times the face term of the momentum
// interpolation, dt (mean(G_c) - G_f) p, over dt: 7.5 % of c_D per unit x on DFG 2D-2 at D/h = 10,
// decaying in three steps. So the step never jumps near the end: once end_time is within
// end_approach_steps steps, the time left is split into the fewest whole steps of at most the step
// asked for (a change of at most 1 / end_approach_steps), and that step is kept to the end while it
// is at most end_overshoot above the step asked for (an adaptive limit drifts while the plan runs);
// beyond that the plan is made anew. A time left that is a whole number of steps keeps its step.
constexpr double end_approach_steps = 100.0;

// The whole number of steps of `step` in `time_left` (relative tolerance 1e-9), or 0.
static double whole_steps(double time_left, double step) {
  const double steps = time_left / step;
  const double n = std::round(steps);
  return n >= 1.0 && std::abs(steps - n) <= 1e-9 * steps ? n : 0.0;
}

static double step_to_end(double limit, double previous, double time_left) {
  if (!(time_left < end_approach_steps * limit)) return limit;
  for (const double step : {previous, limit}) {
    if (!(step > 0.0) || step > (1.0 + end_overshoot) * limit) continue;
    const double n = whole_steps(time_left, step);
    if (n > 0.0) return n == 1.0 ? time_left : step;
  }
  return time_left / std::ceil(time_left / limit);
}

StepLimits step_limits(const Simulation& sim, const VelocityScan& scan) {
  const RunSpec& run = sim.scene().run;
  const double time_left = run.end_time - sim.fluid().time;
  StepLimits limits;
  // Moving walls and inflows set the velocity scale of a fluid at rest (lid-driven start).
  const double wall_speed = boundary_speed_scale(sim.scene().walls);
  const double h = std::min(sim.grid().dx(), sim.grid().dy());
  limits.rate = std::max(scan.max_rate, wall_speed / h);
  limits.advective = limits.rate > 0.0 ? run.cfl / limits.rate : run.max_time_step;
  limits.viscous = viscous_time_step_limit(run, h, sim.fluid_solver().kinematic_viscosity());
  limits.max_time_step = run.max_time_step;
  if (sim.has_bodies()) {
    // The speed over the coming step: the bodies' points as they move now, and a prescribed body's
    // largest speed from its motion law over [t, t + dt] of the step the other limits allow (a
    // body that starts at rest sees the speed it is about to reach). With dt' <= dt the travel
    // dt' max_[t, t + dt'] |U| <= dt' max_[t, t + dt] |U| stays within the limit: one pass suffices.
    const double dt = run.time_step > 0.0 ? run.time_step
                                          : std::min({limits.advective, limits.viscous, limits.max_time_step});
    const double time = sim.fluid().time;
    limits.body_speed = body_travel_speed(sim, time, time + std::min(dt, time_left));
    if (limits.body_speed > 0.0) limits.marker_travel = max_marker_travel_cells * sim.grid().dx() / limits.body_speed;
  }
  return limits;
}

double next_time_step(const Simulation& sim, const VelocityScan& scan) {
  const RunSpec& run = sim.scene().run;
  const double time_left = run.end_time - sim.fluid().time;
  const double previous = sim.fluid().time_step_prev;
  if (run.time_step > 0.0) return step_to_end(run.time_step, previous, time_left);
  return step_to_end(step_limits(sim, scan).adaptive(), previous, time_left);
}

double body_travel_speed(const Simulation& sim, double t0, double t1) {
  double speed = 0.0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    if (body.kind == BodyKind::prescribed) {
      speed = std::max(speed, sim.rigid()[b].prescribed.max_point_speed(t0, t1, 0.5 * body.diameter));
      continue;
    }
    for (const auto& u : body.velocity) speed = std::max(speed, std::hypot(u[0], u[1]));
  }
  return speed;
}

double planned_time_step(const Simulation& sim) {
  return next_time_step(sim, scan_velocity(sim.grid(), sim.fluid()));
}

double viscous_time_step_limit(const RunSpec& run, double h, double kinematic_viscosity) {
  return run.max_viscous_number > 0.0 ? run.max_viscous_number * h * h / kinematic_viscosity : HUGE_VAL;
}

}  // namespace ibms
