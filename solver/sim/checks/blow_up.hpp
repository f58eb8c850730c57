// Blow-up checks after each step (docs/method.md §7): they stop the run with step, time, quantity
// and place, or warn once, as the scene's run.on_*_instability asks.
#pragma once
#include "sim/simulation.hpp"
#include "sim/time_step_limits.hpp"

namespace ibms {

// Throws BlowUpError naming step, time, quantity and place if the state is non-finite or the
// CFL number dt * max_rate exceeds run.max_cfl; with bodies also if a body point is non-finite
// or has left the box in a wall direction (naming body, point and position). Then the fluid
// guard: it first adds the step's input work to the energy budget, so call it once per step of
// length dt, after the step (sim/checks/fluid_guard.hpp).
void check_for_blow_up(Simulation& sim, double dt, const VelocityScan& scan);

}  // namespace ibms
