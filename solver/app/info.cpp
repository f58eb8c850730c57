// Text of `ibms info` (issue 2 item 5; time-step limits of METHOD.md §5 once bodies exist).
#include "app/info.hpp"

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
  // Time step: fixed, or the CFL limit with the largest wall speed as velocity scale.
  const WallsSpec& w = scene.walls;
  const double h = std::min(g.dx(), g.dy());
  const double wall_speed = std::max({std::abs(w.left.speed), std::abs(w.right.speed), std::abs(w.bottom.speed),
                                      std::abs(w.top.speed)});
  text += "\n# time step\n";
  double dt = scene.run.time_step;
  if (dt > 0) {
    text += fmt::format("fixed dt = {:.4g}", dt);
    if (wall_speed > 0) text += fmt::format(" (CFL at the wall speed: {:.3g})", dt * wall_speed / h);
    text += "\n";
  } else {
    dt = std::min(wall_speed > 0 ? scene.run.cfl * h / wall_speed : HUGE_VAL, scene.run.max_time_step);
    text += fmt::format("adaptive: dt = cfl / max(|u|/dx + |v|/dy), cfl = {:.3g}, capped at {:.4g}\n", scene.run.cfl,
                        scene.run.max_time_step);
    if (std::isfinite(dt))
      text += fmt::format("  estimate with |u| = max wall speed {:.4g}: dt = {:.4g}\n", wall_speed, dt);
  }
  text += "  viscous number nu dt / h^2 = " +
          (std::isfinite(dt) ? fmt::format("{:.3g}", scene.fluid.kinematic_viscosity * dt / (h * h)) : "?") +
          " (Crank-Nicolson: no limit)\n";
  if (sim.has_bodies()) {
    // METHOD.md §7 step 7 and §5.3: marker travel and the solid sub-step.
    double body_speed = 0.0;
    for (const BodySpec& b : scene.bodies) body_speed = std::max(body_speed, std::hypot(b.velocity[0], b.velocity[1]));
    text += fmt::format("marker travel: dt <= {:.2g} h / max|U_body| = {:.4g} / max|U_body|", max_marker_travel_cells,
                        max_marker_travel_cells * h);
    if (body_speed > 0) text += fmt::format(" = {:.4g} at the initial speed {:.4g}", max_marker_travel_cells * h / body_speed, body_speed);
    text += "\n";
    double dt_sub = HUGE_VAL;
    for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
      const MassSpringBody& body = sim.bodies()[b];
      const SpectralBounds bounds = spectral_bounds(body);
      const double dt_b = stable_substep(body, /*safety=*/0.5);
      dt_sub = std::min(dt_sub, dt_b);
      text += fmt::format("body {}: {} points, {} springs, mass {:.4g} [mass/length], omega_max <= {:.4g} [1/time], "
                          "damping rate <= {:.4g} [1/time], spring sub-step {:.4g}\n", b, body.n_points(),
                          body.springs.size(), body.total_mass(), std::sqrt(bounds.omega_squared_max),
                          bounds.damping_rate_max, dt_b);
    }
    text += fmt::format("spring sub-step (safety 0.5): {:.4g}\n", dt_sub);
    double contact_limit = HUGE_VAL;
    if (sim.has_contacts()) {
      contact_limit = contact_substep(sim.contact_model(), sim.bodies());
      text += fmt::format("contact sub-step (contact duration / {} at {} x k_Dn): {:.4g}\n",
                          sim.contact_model().steps_per_contact, sim.contact_model().active_pairs_safety, contact_limit);
    }
    if (std::isfinite(dt) && dt > 0)
      text += fmt::format("sub-steps per fluid step at dt = {:.4g}: {}\n", dt,
                          substeps_for(sim.bodies(), dt, contact_limit));
  }
  if (std::isfinite(dt) && dt > 0) {
    const double steps = std::ceil(scene.run.end_time / dt);
    text += fmt::format("estimated steps to end_time {:.6g}: {:.0f}{}\n", scene.run.end_time, steps,
                        scene.run.steady_tolerance > 0 ? " (fewer if the steady state is reached)" : "");
    text += fmt::format("estimated cost: {:.3g} cell-steps\n", steps * static_cast<double>(g.n_cells()));
  }
  return text;
}

}  // namespace ibms
