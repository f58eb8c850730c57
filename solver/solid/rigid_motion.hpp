// Rigid and prescribed bodies (docs/design.md §11): a rigid ring of N_l Lagrangian points and
// a centre point whose positions and velocities follow one rigid motion (centre X_c, angle theta,
// velocity V, rotation rate Omega):  x_l = X_c + R(theta) r_l,  U_l = V + Omega e_z x (x_l - X_c).
//  rigid       Newton-Euler for a uniform disk, m = rho_s pi D^2 / 4, I = m D^2 / 8 [per unit
//              depth], with the total force and torque of the fluid, contacts and buoyant gravity;
//  prescribed  X_c(t) = X0 + V t + A sin(2 pi t/T + phase), theta(t) = Omega t + Theta sin(2 pi t/T + phase).
// Units: lengths [length], angles [rad], forces per unit depth [force/length], torques [force].
#pragma once
#include <array>
#include <string>
#include <vector>

#include "solid/mass_spring_body.hpp"

namespace ibms {

struct RigidState {
  std::array<double, 2> centre{0.0, 0.0};    // X_c [length]
  double angle = 0.0;                        // theta, counter-clockwise [rad]
  std::array<double, 2> velocity{0.0, 0.0};  // V [length/time]
  double angular_velocity = 0.0;             // Omega [1/time]
};

// The prescribed motion of a `prescribed` body; for a rigid body, its initial centre and velocities.
struct PrescribedMotion {
  std::array<double, 2> initial_centre{0.0, 0.0};  // X0 [length]
  std::array<double, 2> velocity{0.0, 0.0};        // V [length/time]
  double angular_velocity = 0.0;                   // Omega [1/time]
  std::array<double, 2> amplitude{0.0, 0.0};       // A [length]
  double angle_amplitude = 0.0;                    // Theta [rad]
  double period = 0.0;                             // T [time]; 0 = no oscillation
  double phase = 0.0;                              // [rad]

  RigidState at(double time) const;  // position, angle and their exact time derivatives
  // The largest speed any point within `radius` of the centre reaches over [t0, t1] [length/time]:
  // max |V + A w cos(psi)| + radius max |Omega + Theta w cos(psi)|, psi = w t + phase, each taken at
  // an end of the range of cos(psi) over the interval (|.| of a linear function of cos(psi) is
  // convex in it): exact for a translating body, an upper bound within the sum of both parts otherwise.
  double max_point_speed(double t0, double t1, double radius) const;
};

struct RigidBody {
  RigidState state;
  std::vector<std::array<double, 2>> offsets;  // r_l: rim points relative to X_c at theta = 0 [length]
  double mass = 0.0;                           // m [mass/length]
  double moment_of_inertia = 0.0;              // I about X_c [mass length]
  PrescribedMotion prescribed;                 // used by kind prescribed only
  // Virtual mass and moment of inertia C_V rho_f (V, V D^2 / 8) (Schwarz, Kempe & Froehlich 2015),
  // on both sides of Newton-Euler: (m + m_v) dV/dt = F + m_v a_prev, a_prev the mean acceleration of
  // the previous fluid step (start_step / end_step); 0 without.
  double virtual_mass = 0.0;                   // [mass/length]
  double virtual_inertia = 0.0;                // [mass length]
  std::array<double, 3> previous_acceleration{0.0, 0.0, 0.0};  // dV/dt, dOmega/dt [length/time^2, 1/time^2]
  std::array<double, 3> step_start{0.0, 0.0, 0.0};             // V, Omega at t^n
};

// The kinematic description of the point set `body` (build_body, kind rigid or prescribed) moving
// as `motion` (rigid: from motion's initial centre, velocity and rotation rate); mass and moment
// of inertia of the uniform disk of body.density.
RigidBody rigid_body_of(const MassSpringBody& body, const PrescribedMotion& motion);

// Positions and velocities of the rim points and the centre point from the rigid state.
void place_points(const RigidBody& rigid, MassSpringBody& body);
// The velocities the points of `rigid` have in the state `s` (rim points, then the centre point):
// U_l = V + Omega e_z x R(theta) r_l [length/time]. `velocity` has one entry per point.
void point_velocities(const RigidBody& rigid, const RigidState& s, std::vector<std::array<double, 2>>& velocity);

// One symplectic Euler step of Newton-Euler with the virtual mass: V += dt (F + m_v a_prev)/(m + m_v),
// Omega += dt (T + I_v alpha_prev)/(I + I_v), X_c += dt V, theta += dt Omega.
void advance_newton_euler(double dt, const std::array<double, 2>& force, double torque, RigidBody& rigid);

// The fluid step's velocities at its start, and at its end the mean acceleration over it (a_prev of
// the next step's virtual mass).
void start_fluid_step(RigidBody& rigid);
void end_fluid_step(double dt, RigidBody& rigid);

}  // namespace ibms
