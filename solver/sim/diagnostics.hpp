// Per-step diagnostics: blow-up detection (non-finite values, CFL beyond the stable limit) with
// the step, time, quantity and place, the adaptive time step, and centre-line profiles.
#pragma once
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace ibms {

// Largest advective rate max(|u|/dx + |v|/dy) over cells, with its cell; a non-finite value is
// reported as found (value = inf) at its first cell. The same sweep gives the fluid guard its
// figures (sim/fluid_guard.hpp): the largest speed |u| with its cell, and the kinetic energy.
struct VelocityScan {
  double max_rate = 0.0;      // [1/time]
  int i = 0, j = 0;           // cell of the maximum (or of the first non-finite value)
  bool finite = true;
  double max_speed = 0.0;     // max |u| over cells [length/time]
  int speed_i = 0, speed_j = 0;  // its cell
  double kinetic_energy = 0.0;   // E = sum |u|^2 dx dy / 2 [length^4/time^2 per unit density and depth]
};
VelocityScan scan_velocity(const Grid& grid, const FluidState& fluid);

// Largest speed of any body point [length/time] (0 without bodies).
double max_body_point_speed(const Simulation& sim);

// The velocity scale of the current state before the fluid is looked at: the fastest moving wall
// or inflow (at its peak) and the fastest body point [length/time]. `ibms info` takes its CFL
// limit and cell Reynolds number from it, and the fluid guard's driving speed starts from it.
double speed_scale(const Simulation& sim);

// Throws BlowUpError naming step, time, quantity and place if the state is non-finite or the
// CFL number dt * max_rate exceeds run.max_cfl; with bodies also if a body point is non-finite
// or has left the box in a wall direction (naming body, point and position). Then the fluid
// guard: it first adds the step's input work to the energy budget, so call it once per step of
// length dt, after the step (sim/fluid_guard.hpp).
void check_for_blow_up(Simulation& sim, double dt, const VelocityScan& scan);

// The time step for the next step: fixed, or cfl / max rate (with moving walls counted) and,
// with bodies, marker travel <= 0.5 h per step (docs/method.md §7 step 7), capped by
// run.max_time_step and by the time left to run.end_time.
double next_time_step(const Simulation& sim, const VelocityScan& scan);

// The step the run takes next from the state of `sim` as it is: next_time_step on a scan of it
// (at construction: the first step, what `ibms info` plans with).
double planned_time_step(const Simulation& sim);

// run.max_viscous_number h^2 / nu, the cap that keeps nu dt / h^2 bounded (the direct forcing's slip
// grows like (nu dt / h^2) h); infinity when run.max_viscous_number is 0 [time].
double viscous_time_step_limit(const RunSpec& run, double h, double kinematic_viscosity);

// Marker travel limit of docs/method.md §7 step 7: a marker moves at most this fraction of h per step.
inline constexpr double max_marker_travel_cells = 0.5;

// Velocity along the vertical centre line (u against y) and the horizontal one (v against x),
// wall values included at both ends; linear interpolation between the two central cells.
struct CentrelineProfiles {
  std::vector<double> y, u;   // x = mid-width
  std::vector<double> x, v;   // y = mid-height
};
CentrelineProfiles centreline_profiles(const Simulation& sim);

}  // namespace ibms
