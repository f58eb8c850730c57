// Text of `ibms info` (time-step limits of docs/method.md §5 once bodies exist).
#include "app/info.hpp"
#include "app/time_step_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/simulation.hpp"
#include "solid/stable_substep.hpp"

namespace ibms {

std::string describe_scene(const Scene& scene) {
  std::string text = "# resolved scene (defaults filled in)\n" + resolved_scene_toml(scene) + "\n";
  const Grid g = grid_from_scene(scene);
  text += fmt::format("# grid\n{} x {} cells, dx = {:.6g}, dy = {:.6g}, periodic x: {}, periodic y: {}\n\n", g.nx,
                      g.ny, g.dx(), g.dy(), g.periodic_x ? "yes" : "no", g.periodic_y ? "yes" : "no");
  const Simulation sim(scene);
  text += "# sides (fluid/boundary_conditions.hpp)\n";
  for (Side side : {Side::left, Side::right, Side::bottom, Side::top}) {
    const char* names[] = {"left", "right", "bottom", "top"};
    const WallSpec* specs[] = {&scene.walls.left, &scene.walls.right, &scene.walls.bottom, &scene.walls.top};
    const BoundarySide& b = sim.boundaries().side(side);
    const SideKind kind = sim.boundaries().kind(g, side);
    std::string what = side_kind_name(kind);
    if (kind == SideKind::wall) what += b.is_moving() ? fmt::format(", tangential speed {:.6g}", b.speed) : ", at rest";
    if (kind == SideKind::inflow)
      what += fmt::format(", {} profile, {} {:.6g} into the box (mean {:.6g} at full factor), {} factor",
                          b.inflow.shape == InflowProfile::Shape::parabolic ? "parabolic" : "uniform",
                          b.inflow.shape == InflowProfile::Shape::parabolic ? "peak" : "speed", b.inflow.velocity,
                          b.inflow.velocity * (b.inflow.shape == InflowProfile::Shape::parabolic ? 2.0 / 3.0 : 1.0),
                          scene_schema::name_of(specs[static_cast<int>(side)]->time_factor));
    if (kind == SideKind::outflow) what += ": zero normal velocity gradient, p = 0";
    text += fmt::format("  {}: {}\n", names[static_cast<int>(side)], what);
  }
  text += "\n# stages per step\n";
  for (const std::string& s : sim.stage_names()) text += "  " + s + "\n";
  const double dt = planned_time_step(sim);  // the run's first step
  if (sim.has_bodies()) {
    text += "\n# bodies (kind: what each step costs)\n";
    for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
      const MassSpringBody& body = sim.bodies()[b];
      const BodySpec& spec = scene.bodies[b];
      std::string cost;
      const double spring_substep = stable_substep(body, /*safety=*/0.5);
      if (body.kind == BodyKind::mass_spring && std::isfinite(dt) && dt > 0 && uses_implicit_springs(body, dt, spring_substep))
        cost = fmt::format("{} points, {} springs, implicit spring steps (spring_integrator = {}; explicit would need "
                           "{:.0f} sub-steps per fluid step){}",
                           body.n_points(), body.springs.size(), scene_schema::name_of(spec.spring_integrator),
                           std::ceil(dt / spring_substep),
                           spec.swelling.enabled ? ", swelling schedule" : "");
      else if (body.kind == BodyKind::mass_spring)
        cost = fmt::format("{} points, {} springs, sub-stepped to its spring period (stable sub-step {:.4g}){}",
                           body.n_points(), body.springs.size(), spring_substep,
                           spec.swelling.enabled ? ", swelling schedule" : "");
      else if (body.kind == BodyKind::rigid)
        cost = fmt::format("{} rim points, Newton-Euler (m = {:.4g}, I = {:.4g}); no spring sub-steps", body.n_surface,
                           sim.rigid()[b].mass, sim.rigid()[b].moment_of_inertia);
      else
        cost = fmt::format("{} rim points, motion given by the scene; forcing and force output only", body.n_surface);
      text += fmt::format("  body {}: {}: {}\n", b, scene_schema::name_of(spec.kind), cost);
    }
  }
  text += '\n';
  text += describe_time_step_limits(scene, sim);
  if (std::isfinite(dt) && dt > 0) {
    const double steps = std::ceil(scene.run.end_time / dt);
    text += fmt::format("estimated steps to end_time {:.6g}: {:.0f}{}\n", scene.run.end_time, steps,
                        scene.run.steady_tolerance > 0 ? " (fewer if the steady state is reached)" : "");
    text += fmt::format("estimated cost: {:.3g} cell-steps\n", steps * static_cast<double>(g.n_cells()));
  }
  return text;
}

}  // namespace ibms
