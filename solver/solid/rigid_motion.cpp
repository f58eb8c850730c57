// Rigid and prescribed body kinematics (see rigid_motion.hpp).
#include "solid/rigid_motion.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace ibms {

namespace {

// The smallest and largest value of cos over [a, b] (a <= b).
std::array<double, 2> cosine_range(double a, double b) {
  if (b - a >= 2.0 * pi) return {-1.0, 1.0};
  std::array<double, 2> range{std::min(std::cos(a), std::cos(b)), std::max(std::cos(a), std::cos(b))};
  if (2.0 * pi * std::ceil(a / (2.0 * pi)) <= b) range[1] = 1.0;             // a multiple of 2 pi inside
  if (pi + 2.0 * pi * std::ceil((a - pi) / (2.0 * pi)) <= b) range[0] = -1.0;  // an odd multiple of pi inside
  return range;
}

}  // namespace

double PrescribedMotion::max_point_speed(double t0, double t1, double radius) const {
  const double omega = period > 0.0 ? 2.0 * pi / period : 0.0;
  const std::array<double, 2> c = omega > 0.0 ? cosine_range(omega * t0 + phase, omega * t1 + phase)
                                              : std::array<double, 2>{0.0, 0.0};
  double centre = 0.0, rotation = 0.0;
  for (const double cosine : c) {
    centre = std::max(centre, std::hypot(velocity[0] + amplitude[0] * omega * cosine,
                                         velocity[1] + amplitude[1] * omega * cosine));
    rotation = std::max(rotation, std::abs(angular_velocity + angle_amplitude * omega * cosine));
  }
  return centre + radius * rotation;
}

RigidState PrescribedMotion::at(double time) const {
  RigidState s;
  double sine = 0.0, cosine_rate = 0.0;  // sin(w t + phase) and d/dt of it
  if (period > 0.0) {
    const double omega = 2.0 * pi / period;
    sine = std::sin(omega*time + phase);
    cosine_rate = omega * std::cos(omega*time + phase);
  }
  for (int d = 0; d < 2; ++d) {
    s.centre[d] = initial_centre[d] + velocity[d]*time + amplitude[d]*sine;
    s.velocity[d] = velocity[d] + amplitude[d]*cosine_rate;
  }
  s.angle = angular_velocity*time + angle_amplitude*sine;
  s.angular_velocity = angular_velocity + angle_amplitude*cosine_rate;
  return s;
}

RigidBody rigid_body_of(const MassSpringBody& body, const PrescribedMotion& motion) {
  RigidBody rigid;
  const auto& centre = body.position[body.centre_index()];
  for (int l = 0; l < body.n_surface; ++l)
    rigid.offsets.push_back({body.position[l][0] - centre[0], body.position[l][1] - centre[1]});
  // Uniform disk per unit depth: m = rho_s pi D^2 / 4, I = m D^2 / 8.
  rigid.mass = body.density * body.solid_area();
  rigid.moment_of_inertia = rigid.mass * body.diameter * body.diameter / 8.0;
  rigid.prescribed = motion;
  if (body.kind == BodyKind::prescribed) {
    rigid.state = rigid.prescribed.at(0.0);
  } else {
    rigid.state = {motion.initial_centre, 0.0, motion.velocity, motion.angular_velocity};
  }
  return rigid;
}

void place_points(const RigidBody& rigid, MassSpringBody& body) {
  const RigidState& s = rigid.state;
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  for (int l = 0; l < body.n_surface; ++l) {
    const auto& r0 = rigid.offsets[l];
    const double rx = c*r0[0] - sn*r0[1], ry = sn*r0[0] + c*r0[1];  // R(theta) r_l
    body.position[l] = {s.centre[0] + rx, s.centre[1] + ry};
  }
  body.position[body.centre_index()] = s.centre;
  point_velocities(rigid, s, body.velocity);
}

void point_velocities(const RigidBody& rigid, const RigidState& s, std::vector<std::array<double, 2>>& velocity) {
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  const std::size_t n_surface = rigid.offsets.size();
  for (std::size_t l = 0; l < n_surface; ++l) {
    const auto& r0 = rigid.offsets[l];
    const double rx = c*r0[0] - sn*r0[1], ry = sn*r0[0] + c*r0[1];  // R(theta) r_l
    velocity[l] = {s.velocity[0] - s.angular_velocity*ry, s.velocity[1] + s.angular_velocity*rx};
  }
  velocity[n_surface] = s.velocity;  // the centre point
}

void advance_newton_euler(double dt, const std::array<double, 2>& force, double torque, RigidBody& rigid) {
  RigidState& s = rigid.state;
  const std::array<double, 3>& a = rigid.previous_acceleration;
  for (int d = 0; d < 2; ++d) s.velocity[d] += dt * (force[d] + rigid.virtual_mass * a[d]) / (rigid.mass + rigid.virtual_mass);
  s.angular_velocity += dt * (torque + rigid.virtual_inertia * a[2]) / (rigid.moment_of_inertia + rigid.virtual_inertia);
  for (int d = 0; d < 2; ++d) s.centre[d] += dt * s.velocity[d];
  s.angle += dt * s.angular_velocity;
}

void start_fluid_step(RigidBody& rigid) {
  rigid.step_start = {rigid.state.velocity[0], rigid.state.velocity[1], rigid.state.angular_velocity};
}

void end_fluid_step(double dt, RigidBody& rigid) {
  const std::array<double, 3> now{rigid.state.velocity[0], rigid.state.velocity[1], rigid.state.angular_velocity};
  for (int k = 0; k < 3; ++k) rigid.previous_acceleration[k] = (now[k] - rigid.step_start[k]) / dt;
}

}  // namespace ibms
