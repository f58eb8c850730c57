// The fluid's instability guard (docs/method.md §7, "The fluid guard"): an energy budget, the
// kinetic energy E against what the boundaries and bodies can have fed it since the start,
//   E^n <= (1 + initial_margin) E_0 + (1 + work_margin) W^n + floor,
// W^n = sum_k dt_k [max(0, P_b^{k-1}, P_b^k) + max(0, P_body^k)], and a speed bound,
//   max |u^n| <= speed_factor V_f,  V_f = max(driving speed of the scene, max |u^0|).
// Kinematic units throughout (per unit fluid density and unit depth): E [length^4/time^2].
#pragma once

namespace ibms {

class Simulation;
struct VelocityScan;

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

// Power the sides feed the fluid at its current state [length^4/time^3]: on a wall or inflow side
// the viscous stress times the side's velocity, nu 2 (u_b - u_c)/h_n . u_b h_t per face; on every
// side the flux of (|u|^2/2 + p) carried in by the normal face velocity (open sides; 0 on walls).
double boundary_power(const Simulation& sim);

// Power the immersed-boundary force of the latest step feeds the fluid, sum_l F_l . U_target,l dV_l
// [length^4/time^3]: the force's work on the velocity it imposes, an upper estimate of the energy
// it adds (u^{n+1} . du >= (|u^{n+1}|^2 - |u^n|^2) / 2).
double body_power(const Simulation& sim);

// Starts the budget from the current state: V_f, E_0, W = 0. The Simulation calls it when built;
// run_simulation calls it again before the first step (a field set from C++ counts as initial).
void start_fluid_guard(Simulation& sim);

// Adds the step's input work dt (max(0, P_b^n, P_b^{n+1}) + max(0, P_body)) to W.
void account_fluid_input(Simulation& sim, double dt);

// Stops the run (run.on_fluid_instability = "stop": BlowUpError naming step, time, quantity and
// place) or warns once ("warn") if the kinetic energy exceeds its budget or the largest speed
// exceeds speed_factor V_f.
void check_fluid_guard(Simulation& sim, const VelocityScan& scan);

}  // namespace ibms
