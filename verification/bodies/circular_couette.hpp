// Circular Couette flow between two concentric prescribed cylinders, the immersed-boundary
// verification of test_circular_couette.cpp and the forcing-pass study of bench/bench_forcing_passes:
// the inner cylinder (radius R1) turns at Omega, the outer one (R2) is fixed, in a walled unit box.
// Steady solution in the annulus u_theta = A r + B / r, A = -Omega R1^2 / (R2^2 - R1^2),
// B = Omega R1^2 R2^2 / (R2^2 - R1^2), u_r = 0 (exact at any Reynolds number).
#pragma once
#include <string>
#include <chrono>
#include <cmath>

#include "body_scenes.hpp"
#include "scene/scene_schema.hpp"

namespace ibms::test {

struct CircularCouette {
  static constexpr double inner_radius = 0.15, outer_radius = 0.35, rotation_rate = 1.0;  // R1, R2, Omega
  static constexpr double kinematic_viscosity = 0.1;  // Re = Omega R1 (R2 - R1) / nu = 0.3
  static constexpr double viscous_number = 0.5;       // nu dt / h^2 on the finer grids
  static constexpr double end_time = 0.4;
  // Off the grid's symmetry lines, the same physical place at every resolution.
  static constexpr std::array<double, 2> centre{0.503, 0.498};

  static double exact_u_theta(double r) {
    const double denominator = outer_radius * outer_radius - inner_radius * inner_radius;
    const double a = -rotation_rate * inner_radius * inner_radius / denominator;
    const double b = rotation_rate * inner_radius * inner_radius * outer_radius * outer_radius / denominator;
    return a * r + b / r;
  }
  // The exact field everywhere: rigid rotation inside R1, the Couette profile, rest outside R2.
  static double u_theta_everywhere(double r) {
    return r < inner_radius ? rotation_rate * r : (r > outer_radius ? 0.0 : exact_u_theta(r));
  }
};

// Errors relative to the inner rim speed Omega R1 [-], and the run's cost.
struct CouetteResult {
  double l2 = 0.0, max = 0.0;  // |u - u_exact| over the cells with R1 <= r <= R2
  double slip = 0.0;           // max |U - J u| over the markers of both cylinders after the last step
  double ms_per_step = 0.0;
  // Effective radii of the forced cylinders, from the least-squares fit u_theta = A r + B / r over
  // the cells with R1 + 3h <= r <= R2 - 3h (outside the kernels' reach): the inner rim speed is met
  // at R1e = sqrt(B / (Omega - A)), rest at R2e = sqrt(-B / A). In cells, positive when the body
  // looks larger than its rim: (R1e - R1) / h and (R2 - R2e) / h.
  double inner_growth_cells = 0.0, outer_growth_cells = 0.0;
};

// n x n cells, markers spaced ~ h, dt = min(0.5 h / (Omega R1), viscous_number h^2 / nu), started from
// the exact solution, run to end_time: the distance to the discrete steady state decays like
// exp(-nu pi^2 t / (R2 - R1)^2), so t = 0.4 leaves e^-9.9 of it.
inline CouetteResult run_circular_couette(int n, int forcing_passes, double marker_retraction = 0.0,
                                          const std::string& coupling = "uhlmann",
                                          const std::string& constrained_velocity = "cells") {
  using C = CircularCouette;
  Scene scene;
  scene.source_file = "(circular Couette)";
  scene.domain = {1.0, 1.0, n, n, false, false};
  scene.fluid.kinematic_viscosity = C::kinematic_viscosity;
  scene.ibm.forcing_passes = forcing_passes;
  scene.ibm.marker_retraction = marker_retraction;
  scene.ibm.coupling = scene_schema::parse_choice<IbmSpec::Coupling>(coupling).value();
  scene.ibm.slip_tolerance = 1e-4;
  scene.ibm.constrained_velocity =
      scene_schema::parse_choice<IbmSpec::ConstrainedVelocity>(constrained_velocity).value();
  // Prescribed bodies move as given: the inner-fluid term would only enter their reported force,
  // and its fan-triangle overlaps of the large outer cylinder would cost 4x the whole run.
  scene.ibm.inner_fluid_inertia = IbmSpec::InnerFluidInertia::none;
  const double h = 1.0 / n;
  scene.bodies.push_back(prescribed_cylinder(C::centre, 2 * C::inner_radius, h, C::rotation_rate));
  scene.bodies.push_back(prescribed_cylinder(C::centre, 2 * C::outer_radius, h, 0.0));
  Simulation sim(scene);
  const Grid& g = sim.grid();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double rx = g.x_centre(i) - C::centre[0], ry = g.y_centre(j) - C::centre[1];
      const double r = std::hypot(rx, ry), u_theta = C::u_theta_everywhere(r);
      sim.fluid().velocity_x(i, j) = -u_theta * ry / std::max(r, 1e-300);
      sim.fluid().velocity_y(i, j) = u_theta * rx / std::max(r, 1e-300);
    }
  sim.fluid_solver().initialise_faces(sim.fluid());
  const double dt = std::min(0.5 * h / (C::rotation_rate * C::inner_radius),
                             C::viscous_number * h * h / C::kinematic_viscosity);
  const auto start = std::chrono::steady_clock::now();
  run_to(sim, C::end_time, dt);
  CouetteResult result;
  result.ms_per_step = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                       static_cast<double>(sim.fluid().step);
  const double speed = C::rotation_rate * C::inner_radius;
  double sum = 0.0, area = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double rx = g.x_centre(i) - C::centre[0], ry = g.y_centre(j) - C::centre[1];
      const double r = std::hypot(rx, ry);
      if (r < C::inner_radius || r > C::outer_radius) continue;
      const double u_exact = -C::exact_u_theta(r) * ry / r, v_exact = C::exact_u_theta(r) * rx / r;
      const double error = std::hypot(sim.fluid().velocity_x(i, j) - u_exact, sim.fluid().velocity_y(i, j) - v_exact);
      sum += error * error * g.cell_area();
      area += g.cell_area();
      result.max = std::max(result.max, error / speed);
    }
  result.l2 = std::sqrt(sum / area) / speed;
  // Least squares for (A, B) in u_theta = A r + B / r: normal equations of the basis (r, 1/r).
  double srr = 0.0, sr1 = 0.0, s11 = 0.0, sur = 0.0, su1 = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double rx = g.x_centre(i) - C::centre[0], ry = g.y_centre(j) - C::centre[1];
      const double r = std::hypot(rx, ry);
      if (r < C::inner_radius + 3 * h || r > C::outer_radius - 3 * h) continue;
      const double u_theta = (-sim.fluid().velocity_x(i, j) * ry + sim.fluid().velocity_y(i, j) * rx) / r;
      srr += r * r; sr1 += 1.0; s11 += 1.0 / (r * r); sur += u_theta * r; su1 += u_theta / r;
    }
  const double det = srr * s11 - sr1 * sr1;
  const double a = (sur * s11 - su1 * sr1) / det, b = (srr * su1 - sr1 * sur) / det;
  result.inner_growth_cells = (std::sqrt(b / (C::rotation_rate - a)) - C::inner_radius) / h;
  result.outer_growth_cells = (C::outer_radius - std::sqrt(-b / a)) / h;
  result.slip = std::max(rim_slip(sim, 0), rim_slip(sim, 1)) / speed;
  return result;
}

}  // namespace ibms::test
