// Control-volume force of every body over the steps (control_volume_monitor.hpp).
#include "sim/checks/control_volume_monitor.hpp"

#include <algorithm>

namespace ibms {
namespace {

FlowFields flow_fields(const FluidState& f) {
  return {f.velocity_x, f.velocity_y, f.velocity_face_x, f.velocity_face_y, f.pressure};
}

// Bounding box of the rim points.
void bounding_box(const MassSpringBody& body, ForceVector& lower, ForceVector& upper) {
  lower = upper = body.position[0];
  for (int p = 1; p < body.n_surface; ++p)
    for (int d = 0; d < 2; ++d) {
      lower[d] = std::min(lower[d], body.position[p][d]);
      upper[d] = std::max(upper[d], body.position[p][d]);
    }
}

}  // namespace

Vec2 body_velocity(const Simulation& sim, std::size_t b) {
  const MassSpringBody& body = sim.bodies()[b];
  if (body.kind != BodyKind::mass_spring) return sim.rigid()[b].state.velocity;
  Vec2 velocity{0.0, 0.0};
  for (int p = 0; p < body.n_points(); ++p)
    for (int d = 0; d < 2; ++d) velocity[d] += body.mass[p] * body.velocity[p][d];
  for (double& v : velocity) v /= body.total_mass();
  return velocity;
}

Vec2 body_volume_momentum(const Simulation& sim, std::size_t b) {
  const double area = polygon_area(sim.bodies()[b]);
  const Vec2 velocity = body_velocity(sim, b);
  return {area * velocity[0], area * velocity[1]};
}

ControlVolumeMonitor::ControlVolumeMonitor(const Simulation& sim)
    : bodies_(sim.grid().nx >= 5 && sim.grid().ny >= 5 ? sim.bodies().size() : 0) {}

const BodyControlVolume& ControlVolumeMonitor::body(std::size_t b) const {
  static const BodyControlVolume none;
  return b < bodies_.size() ? bodies_[b] : none;
}

void ControlVolumeMonitor::begin_step(const Simulation& sim) {
  const Grid& g = sim.grid();
  const FluidState& f = sim.fluid();
  const double nu = sim.fluid_solver().kinematic_viscosity();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    BodyControlVolume& cv = bodies_[b];
    const MassSpringBody& body = sim.bodies()[b];
    ForceVector lower{}, upper{};
    bounding_box(body, lower, upper);
    const CellRectangle rectangle = control_volume_around(g, lower, upper, body.diameter);
    cv.start_clearance = control_volume_clearance(g, rectangle, lower, upper);
    if (cv.after_step == f.step && rectangle == cv.rectangle) {
      cv.before = cv.after;  // the same fields on the same rectangle: the same bits
    } else {
      cv.rectangle = rectangle;
      cv.before = control_volume_terms(g, rectangle, flow_fields(f), nu);
    }
    cv.body_momentum_before = body_volume_momentum(sim, b);
  }
}

void ControlVolumeMonitor::end_step(const Simulation& sim, double dt) {
  const FluidState& f = sim.fluid();
  const double nu = sim.fluid_solver().kinematic_viscosity();
  const double rho = sim.fluid_density();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    BodyControlVolume& cv = bodies_[b];
    cv.after = control_volume_terms(sim.grid(), cv.rectangle, flow_fields(f), nu);
    cv.after_step = f.step;
    cv.force = control_volume_force(cv.before, cv.after, dt, rho);
    cv.clearance = cv.start_clearance;
    const Vec2 body_momentum = body_volume_momentum(sim, b);
    for (int d = 0; d < 2; ++d) cv.force[d] += rho * (body_momentum[d] - cv.body_momentum_before[d]) / dt;
  }
}

}  // namespace ibms
