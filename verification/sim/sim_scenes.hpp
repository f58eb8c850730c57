// Small scenes for the coupling tests of verification/sim (built in code, no TOML).
#pragma once
#include "scene/scene.hpp"

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

}  // namespace ibms::test
