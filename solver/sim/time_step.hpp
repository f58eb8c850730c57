// One step n -> n+1 of docs/method.md §7.
#pragma once
#include "sim/simulation.hpp"

namespace ibms {

// Advances the fluid and the bodies of `sim` from t^n to t^{n+1} = t^n + dt (sim/time_step.cpp).
void advance_one_step(Simulation& sim, double dt);

}  // namespace ibms
