// The fluid's instability guard (docs/method.md §7, "The fluid guard"): its state is
// FluidGuard (sim/instability_bounds.hpp); these functions start it, feed it the step's input work
// and check the kinetic energy and the largest speed against it.
#pragma once
#include "sim/instability_bounds.hpp"

namespace ibms {

class Simulation;
struct VelocityScan;

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
