// Building a Simulation from a Scene: grid, wall motions, fluid solver, initial state.
#include "sim/simulation.hpp"

namespace ibms {

Grid grid_from_scene(const Scene& scene) {
  const DomainSpec& d = scene.domain;
  return Grid(d.cells_x, d.cells_y, d.length_x, d.length_y, d.periodic_x, d.periodic_y);
}

FluidBoundaries boundaries_from_scene(const Scene& scene) {
  auto motion = [](const WallSpec& w) { return WallMotion{w.speed, w.stop_time}; };
  FluidBoundaries bc;
  bc.periodic_x = scene.domain.periodic_x;
  bc.periodic_y = scene.domain.periodic_y;
  bc.left = motion(scene.walls.left);
  bc.right = motion(scene.walls.right);
  bc.bottom = motion(scene.walls.bottom);
  bc.top = motion(scene.walls.top);
  return bc;
}

Simulation::Simulation(const Scene& scene)
    : scene_(scene),
      grid_(grid_from_scene(scene)),
      fluid_solver_(grid_, scene.fluid.kinematic_viscosity, boundaries_from_scene(scene)),
      fluid_(fluid_solver_.make_state()) {
  fluid_solver_.initialise_faces(fluid_);  // fluid at rest: faces 0, projection is a no-op
}

std::vector<std::string> Simulation::stage_names() const {
  std::vector<std::string> stages;
  if (has_bodies()) stages.push_back("schedules (wall velocities, swelling)");
  else stages.push_back("schedules (wall velocities)");
  stages.push_back("predictor (AB2 convection, Crank-Nicolson diffusion by DST Helmholtz)");
  if (has_bodies()) stages.push_back("immersed-boundary forcing");
  stages.push_back("projection (momentum interpolation, DCT/FFT Poisson)");
  if (has_bodies()) stages.push_back("bodies (sub-stepped mass-spring update)");
  stages.push_back("diagnostics");
  if (scene_.run.steady_tolerance > 0) stages.push_back("steady-state stop");
  return stages;
}

}  // namespace ibms
