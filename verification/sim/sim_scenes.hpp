// Small scenes for the coupling tests of verification/sim (built in code, no TOML).
#pragma once
#include "scene/scene.hpp"
#include "sim/simulation.hpp"

namespace ibms::test {

// One wheel of diameter `diameter` centred in a unit box of n x n cells, fluid rho_f = 1.
inline Scene one_body_scene(int n, bool periodic, double diameter, double density, double stiffness) {
  Scene scene;
  scene.source_file = "(test scene)";
  scene.domain = {1.0, 1.0, n, n, periodic, periodic};
  scene.fluid.density = 1.0;
  scene.fluid.kinematic_viscosity = 0.01;
  BodySpec body;
  body.centre = {0.5, 0.5};
  body.diameter = diameter;
  body.n_surface_points = 48;  // spacing pi 0.25/48 = 1.05 h at n = 64
  body.density = density;
  body.spring_stiffness = stiffness;
  body.restitution_coefficient = 0.5;
  scene.bodies.push_back(body);
  return scene;
}

// Momentum of the fluid, sum rho_f u h^2, and of the body points, sum M U [mass length/time].
inline Vec2 fluid_momentum(const Simulation& sim) {
  Vec2 p{0.0, 0.0};
  const Grid& g = sim.grid();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      p[0] += sim.fluid_density() * sim.fluid().velocity_x(i, j) * g.cell_area();
      p[1] += sim.fluid_density() * sim.fluid().velocity_y(i, j) * g.cell_area();
    }
  return p;
}

inline Vec2 body_momentum(const Simulation& sim) {
  Vec2 p{0.0, 0.0};
  for (const MassSpringBody& body : sim.bodies())
    for (int k = 0; k < body.n_points(); ++k)
      for (int d = 0; d < 2; ++d) p[d] += body.mass[k] * body.velocity[k][d];
  return p;
}

}  // namespace ibms::test
