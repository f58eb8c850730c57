// Every time-step limit of a scene for `ibms info` (docs/method.md §5 and §7): the
// advective CFL limit, the explicit viscous bound (not binding: Crank-Nicolson), marker travel,
// per body the spring period and the damping limit of symplectic Euler, the DEM contact duration;
// the sub-steps the solid will take, and a WARNING line wherever a fixed time step exceeds the
// safe fraction of a limit that is not sub-stepped; the von Neumann CFL limit of AB2 + CN at the
// scene's cell Reynolds number, with a note when the step's CFL number is above it.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sim/simulation.hpp"

namespace ibms {

struct TimeStepLimit {
  std::string name;        // e.g. "CFL (advective)"
  double limit = 0.0;      // stability bound [time]; inf when there is none (or no scale yet)
  double safe_fraction;    // the run keeps dt (or the sub-step) below safe_fraction * limit [-]
  bool sub_stepped;        // handled by solid sub-stepping inside a fluid step
  std::string note;        // how it was computed
};

// The limits at the initial state of `sim` (built from `scene`).
std::vector<TimeStepLimit> time_step_limits(const Scene& scene, const Simulation& sim);

// The text block of `ibms info`: limits table, time step (the run's first, sim/time_step_limits.hpp
// planned_time_step), sub-steps and warnings.
std::string describe_time_step_limits(const Scene& scene, const Simulation& sim);

}  // namespace ibms
