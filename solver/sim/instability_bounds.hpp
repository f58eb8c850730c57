// The state of the run's instability guards (sim/checks/). The fluid's guard (docs/method.md §7,
// "The fluid guard"): an energy budget, the kinetic energy E against what the boundaries and
// bodies can have fed it since the start,
//   E^n <= (1 + initial_margin) E_0 + (1 + work_margin) W^n + floor,
// W^n = sum_k dt_k [max(0, P_b^{k-1}, P_b^k) + max(0, P_body^k)], and a speed bound,
//   max |u^n| <= speed_factor V_f,  V_f = max(driving speed of the scene, max |u^0|).
// Kinematic units throughout (per unit fluid density and unit depth): E [length^4/time^2].
#pragma once
#include <vector>

namespace ibms {

struct FluidGuard {
  // Margins (docs/method.md §7): the discrete scheme's own gain on the initial energy (AB2 adds
  // O(dt^3) per step; the stable runs of bench_fluid_stability stay below 1.01 E_0), the error of
  // the boundary and marker power estimates, and the factor on the speed scale (the stable runs of
  // bench_fluid_stability reach 1.42 V_f, the unstable adaptive ones 2-3.5 V_f).
  static constexpr double initial_margin = 0.02;  // [-]
  static constexpr double work_margin = 0.5;      // [-]
  static constexpr double speed_factor = 1.75;    // [-]
  // A fluid with nothing driving it holds round-off only: 1e-6 of E_V = V_f^2 A / 2 (A the box area).
  static constexpr double floor_fraction = 1e-6;  // [-]

  double speed_scale = 0.0;     // V_f [length/time]
  double initial_energy = 0.0;  // E_0 [length^4/time^2]
  double input_work = 0.0;      // W^n [length^4/time^2]
  double boundary_power = 0.0;  // P_b of the latest state [length^4/time^3]
  double energy_floor = 0.0;    // floor_fraction E_V [length^4/time^2]
  bool warned = false;          // run.on_fluid_instability = "warn": said once
  // The largest max |u| / V_f and E / budget checked since the guard started (`ibms run` prints them) [-].
  double largest_speed_ratio = 0.0, largest_energy_ratio = 0.0;

  double energy_budget() const {
    return (1.0 + initial_margin) * initial_energy + (1.0 + work_margin) * input_work + energy_floor;
  }
};

// The instability guards' scales (sim/checks/blow_up.cpp, sim/checks/fluid_guard.hpp). driving_speed is the
// speed that drives the scene, V_drive = the largest of the wall speeds, the initial body point
// speeds, the prescribed bodies' point speeds, the swelling rates and the free-fall speed
// sqrt(2 |1 - rho_f/rho_s| |g| L) over the box diagonal L (at least L / 1000 per end_time); per
// body, the most kinetic energy it can physically reach is E_max = energy_factor (M V_drive^2 / 2 +
// E_spring(t = 0)), M its largest (swollen) mass.
struct InstabilityBounds {
  static constexpr double energy_factor = 4.0;  // twice every speed
  double driving_speed = 0.0;
  std::vector<double> body_energy_scale;  // M V_drive^2 / 2 + E_spring(t = 0) of each body
  mutable bool warned = false;  // run.on_body_instability = "warn": said once
  // The fluid's energy budget and speed bound, started by run_simulation from the state the run
  // starts with (start_fluid_guard, sim/checks/fluid_guard.hpp), or restored from a checkpoint.
  FluidGuard fluid_guard;
};

}  // namespace ibms
