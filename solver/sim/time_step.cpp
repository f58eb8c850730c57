// One step n -> n+1 of METHOD.md §7. Read top to bottom; each line is one substep.
#include "sim/simulation.hpp"

namespace ibms {

void advance_one_step(Simulation& sim, double dt) {
  FluidState& fluid = sim.fluid();
  StageTimers& timers = sim.timers();
  {
    auto t = timers.time(Stage::predictor);
    sim.fluid_solver().predict_momentum(fluid, dt, nullptr, nullptr);  // u~, METHOD.md §2.3 step 1
  }
  {
    auto t = timers.time(Stage::projection);
    sim.last_projection = sim.fluid_solver().project_smac(fluid, dt);  // u^{n+1}, U_f^{n+1}, p^{n+1}
  }
}

}  // namespace ibms
