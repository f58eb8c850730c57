// Text of `ibms info` (issue 2 item 5; time-step limits of METHOD.md §5 once bodies exist).
#include "app/info.hpp"
#include "app/time_step_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/scene_reader.hpp"
#include "sim/diagnostics.hpp"
#include "sim/simulation.hpp"
#include "solid/stable_substep.hpp"

namespace ibms {

std::string describe_scene(const Scene& scene) {
  std::string text = "# resolved scene (defaults filled in)\n" + resolved_scene_toml(scene) + "\n";
  const Grid g = grid_from_scene(scene);
  text += fmt::format("# grid\n{} x {} cells, dx = {:.6g}, dy = {:.6g}, periodic x: {}, periodic y: {}\n\n", g.nx,
                      g.ny, g.dx(), g.dy(), g.periodic_x ? "yes" : "no", g.periodic_y ? "yes" : "no");
  const Simulation sim(scene);
  text += "# stages per step\n";
  for (const std::string& s : sim.stage_names()) text += "  " + s + "\n";
  text += "\n" + describe_time_step_limits(scene, sim);
  const double dt = planned_time_step(scene);
  if (std::isfinite(dt) && dt > 0) {
    const double steps = std::ceil(scene.run.end_time / dt);
    text += fmt::format("estimated steps to end_time {:.6g}: {:.0f}{}\n", scene.run.end_time, steps,
                        scene.run.steady_tolerance > 0 ? " (fewer if the steady state is reached)" : "");
    text += fmt::format("estimated cost: {:.3g} cell-steps\n", steps * static_cast<double>(g.n_cells()));
  }
  return text;
}

}  // namespace ibms
