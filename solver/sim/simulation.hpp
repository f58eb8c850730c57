// The Simulation: everything one run holds (grid, fluid solver and state, stage list, timers),
// built once from a validated Scene. sim/ is the only place where modules meet (DESIGN.md §2).
// Schemes and stages are chosen here, when the Simulation is built, never inside the step.
#pragma once
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "fluid/fluid_solver.hpp"
#include "scene/scene.hpp"
#include "sim/stage_timers.hpp"

namespace ibms {

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  const Scene& scene() const { return scene_; }
  const Grid& grid() const { return grid_; }
  FluidSolver& fluid_solver() { return fluid_solver_; }
  FluidState& fluid() { return fluid_; }
  const FluidState& fluid() const { return fluid_; }
  StageTimers& timers() { return timers_; }
  double fluid_density() const { return scene_.fluid.density; }

  bool has_bodies() const { return scene_.has_bodies(); }
  // Names of the pipeline stages this scene runs, in order (`ibms info` prints them).
  std::vector<std::string> stage_names() const;

  ProjectionStats last_projection;  // diagnostics of the latest step

 private:
  Scene scene_;
  Grid grid_;
  FluidSolver fluid_solver_;
  FluidState fluid_;
  StageTimers timers_;
};

// Builders shared with `ibms info` and tests.
Grid grid_from_scene(const Scene& scene);
FluidBoundaries boundaries_from_scene(const Scene& scene);

// One step n -> n+1 of METHOD.md §7 (sim/time_step.cpp).
void advance_one_step(Simulation& sim, double dt);

}  // namespace ibms
