// The run's time-step rule (docs/method.md §7): the velocity scan it reads, the speed scales, and
// the next step from the CFL number, the marker travel, the viscous number, run.max_time_step and
// the approach to run.end_time. `ibms info` prints the limits it plans with.
#pragma once
#include <algorithm>
#include <cmath>

#include "sim/simulation.hpp"

namespace ibms {

// Largest advective rate max(|u|/dx + |v|/dy) over cells, with its cell; a non-finite value is
// reported as found (value = inf) at its first cell. The same sweep gives the fluid guard its
// figures (sim/checks/fluid_guard.hpp): the largest speed |u| with its cell, and the kinetic energy.
struct VelocityScan {
  double max_rate = 0.0;      // [1/time]
  int i = 0, j = 0;           // cell of the maximum (or of the first non-finite value)
  bool finite = true;
  double max_speed = 0.0;     // max |u| over cells [length/time]
  int speed_i = 0, speed_j = 0;  // its cell
  double kinetic_energy = 0.0;   // E = sum |u|^2 dx dy / 2 [length^4/time^2 per unit density and depth]
};
VelocityScan scan_velocity(const Grid& grid, const FluidState& fluid);

// The limits of the step as the run takes them (docs/method.md §7 step 7), computed once here for
// next_time_step and for `ibms info`, which prints them.
struct StepLimits {
  double rate = 0.0;                // max(scan's |u|/dx + |v|/dy, U_walls / min(dx, dy)) [1/time]
  double advective = HUGE_VAL;      // run.cfl / rate; run.max_time_step while rate is 0 [time]
  double viscous = HUGE_VAL;        // viscous_time_step_limit [time]
  double max_time_step = HUGE_VAL;  // run.max_time_step [time]
  double body_speed = 0.0;          // body_travel_speed over the coming step (below) [length/time]
  double marker_travel = HUGE_VAL;  // max_marker_travel_cells dx / body_speed [time]
  double adaptive() const {         // the adaptive step before the approach to end_time [time]
    return std::min(std::min({advective, viscous, max_time_step}), marker_travel);
  }
};
// The coming step is the fixed run.time_step, or the adaptive one the other limits allow; the
// bodies' speed is taken over it (a prescribed body at its largest from its motion law), both cut
// at the time left to run.end_time.
StepLimits step_limits(const Simulation& sim, const VelocityScan& scan);

// The time step for the next step: fixed, or cfl / max rate (with moving walls counted), capped
// by run.max_viscous_number and run.max_time_step, and, with bodies, marker travel <= 0.5 h over
// the step (docs/method.md §7 step 7; prescribed bodies at their largest speed over the step), and
// by the time left to run.end_time.
double next_time_step(const Simulation& sim, const VelocityScan& scan);

// The speed the markers travel at over [t0, t1]: the largest point speed of the rigid and
// mass-spring bodies now, and of the prescribed bodies the largest their motion law reaches over
// the interval [length/time].
double body_travel_speed(const Simulation& sim, double t0, double t1);

// The step the run takes next from the state of `sim` as it is: next_time_step on a scan of it
// (at construction: the first step, what `ibms info` plans with).
double planned_time_step(const Simulation& sim);

// run.max_viscous_number h^2 / nu, the cap that keeps nu dt / h^2 bounded (the direct forcing's slip
// grows like (nu dt / h^2) h); infinity when run.max_viscous_number is 0 [time].
double viscous_time_step_limit(const RunSpec& run, double h, double kinematic_viscosity);

// Marker travel limit of docs/method.md §7 step 7: a marker moves at most this fraction of h per step.
inline constexpr double max_marker_travel_cells = 0.5;

// Near end_time the step keeps its length while it is at most this fraction above the limits
// (the approach to end_time in time_step_limits.cpp: no jump of the step near the end).
inline constexpr double end_overshoot = 0.05;

}  // namespace ibms
