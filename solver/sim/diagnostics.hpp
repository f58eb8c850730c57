// Per-step diagnostics: blow-up detection (non-finite values, CFL beyond the stable limit) with
// the step, time, quantity and place, the adaptive time step, and centre-line profiles.
#pragma once
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace ibms {

// Largest advective rate max(|u|/dx + |v|/dy) over cells, with its cell; a non-finite value is
// reported as found (value = inf) at its first cell.
struct VelocityScan {
  double max_rate = 0.0;      // [1/time]
  int i = 0, j = 0;           // cell of the maximum (or of the first non-finite value)
  bool finite = true;
};
VelocityScan scan_velocity(const Grid& grid, const FluidState& fluid);

// Largest speed of any body point [length/time] (0 without bodies).
double max_body_point_speed(const Simulation& sim);

// Throws BlowUpError naming step, time, quantity and place if the state is non-finite or the
// CFL number dt * max_rate exceeds run.max_cfl; with bodies also if a body point is non-finite
// or has left the box in a wall direction (naming body, point and position).
void check_for_blow_up(const Simulation& sim, double dt, const VelocityScan& scan);

// The time step for the next step: fixed, or cfl / max rate (with moving walls counted) and,
// with bodies, marker travel <= 0.5 h per step (docs/method.md §7 step 7), capped by
// run.max_time_step and by the time left to run.end_time.
double next_time_step(const Simulation& sim, const VelocityScan& scan);

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
