// Scenes and helpers for the immersed-boundary verification of rigid and prescribed bodies,
// built in code. Markers: N_l = round(pi D / h), spacing ~ h (Uhlmann 2005).
#pragma once
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "ibm/ib_operators.hpp"
#include "scene/scene.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

namespace ibms::test {

inline int markers_for(double diameter, double h) {
  return std::max(8, static_cast<int>(std::lround(pi * diameter / h)));
}

// A disk body of `kind` with markers spaced ~ h, at rest.
inline BodySpec disk_body(BodySpec::Kind kind, std::array<double, 2> centre, double diameter, double h) {
  BodySpec body;
  body.kind = kind;
  body.centre = centre;
  body.diameter = diameter;
  body.n_surface_points = markers_for(diameter, h);
  return body;
}

// A prescribed cylinder turning at `angular_velocity` about its fixed centre.
inline BodySpec prescribed_cylinder(std::array<double, 2> centre, double diameter, double h, double angular_velocity) {
  BodySpec body = disk_body(BodySpec::Kind::prescribed, centre, diameter, h);
  body.angular_velocity = angular_velocity;
  return body;
}

inline BodySpec rigid_disk(std::array<double, 2> centre, double diameter, double h, double density) {
  BodySpec body = disk_body(BodySpec::Kind::rigid, centre, diameter, h);
  body.density = density;
  return body;
}

// n steps of equal length to end_time.
inline void run_to(Simulation& sim, double end_time, double max_dt) {
  const double remaining = end_time - sim.fluid().time;
  const int n = static_cast<int>(std::ceil(remaining / max_dt - 1e-9));
  for (int k = 0; k < n; ++k) advance_one_step(sim, remaining / n);
}

// Largest |U_target - J u| over the markers of body b with the current (projected) velocity:
// the slip the no-slip condition keeps after the step [length/time].
inline double rim_slip(Simulation& sim, std::size_t b) {
  const BodyCoupling& c = sim.markers()[b];
  std::vector<Vec2> interpolated(c.marker.size());
  std::vector<Vec2> marker(c.marker.size()), target(c.marker.size());
  const MassSpringBody& body = sim.bodies()[b];
  for (int l = 0; l < body.n_surface; ++l) {
    marker[l] = body.position[l];
    target[l] = body.velocity[l];
  }
  interpolate(sim.grid(), sim.kernel(), wall_velocities_at(sim.boundaries(), sim.fluid().time), sim.fluid().velocity_x,
              sim.fluid().velocity_y, marker, interpolated);
  double slip = 0.0;
  for (std::size_t l = 0; l < marker.size(); ++l)
    slip = std::max(slip, std::hypot(target[l][0] - interpolated[l][0], target[l][1] - interpolated[l][1]));
  return slip;
}

}  // namespace ibms::test
