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

// Throws BlowUpError naming step, time, quantity and place if the state is non-finite or the
// CFL number dt * max_rate exceeds run.max_cfl.
void check_for_blow_up(const Simulation& sim, double dt, const VelocityScan& scan);

// The time step for the next step: fixed, or cfl / max rate (with moving walls counted), capped
// by run.max_time_step and by the time left to run.end_time.
double next_time_step(const Simulation& sim, const VelocityScan& scan);

// Velocity along the vertical centre line (u against y) and the horizontal one (v against x),
// wall values included at both ends; linear interpolation between the two central cells.
struct CentrelineProfiles {
  std::vector<double> y, u;   // x = mid-width
  std::vector<double> x, v;   // y = mid-height
};
CentrelineProfiles centreline_profiles(const Simulation& sim);

}  // namespace ibms
