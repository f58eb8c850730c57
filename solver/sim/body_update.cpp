// Sub-stepped mass-spring update of the bodies, METHOD.md §5.3 (see body_update.hpp).
#include "sim/body_update.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solid/stable_substep.hpp"
#include "solid/symplectic_euler.hpp"

namespace ibms {

void no_contact_forces(const std::vector<MassSpringBody>&, double, std::vector<std::vector<Vec2>>&) {}

void apply_swelling_schedules(const std::vector<SwellingSchedule>& swelling, double time,
                              std::vector<MassSpringBody>& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (swelling[b].enabled) apply_swelling(bodies[b], swelling[b].diameter(time));
}

int substeps_for(const std::vector<MassSpringBody>& bodies, double dt, double max_substep, SpectralWorkspace* work) {
  SpectralWorkspace local;
  SpectralWorkspace& scratch = work != nullptr ? *work : local;
  double dt_s = max_substep;
  for (const MassSpringBody& body : bodies) dt_s = std::min(dt_s, stable_substep(body, /*safety=*/0.5, scratch));
  if (!(dt_s > 0.0)) throw std::runtime_error("advance_bodies: non-positive stable sub-step");
  return std::max(1, static_cast<int>(std::ceil(dt / dt_s * (1.0 - 1e-12))));
}

namespace {

// Rigid body: total force and torque about X_c of the frozen hydrodynamic load, this sub-step's
// contact forces on the rim points and the buoyancy-corrected weight; one Newton-Euler step.
void advance_rigid(const SolidStepInputs& in, double dt_sub, const BodyCoupling& c,
                   const std::vector<Vec2>& contact_force, RigidBody& rigid, MassSpringBody& body) {
  const double buoyancy_factor = 1.0 - in.fluid_density / body.density;  // (rho_s - rho_f) / rho_s
  Vec2 force = c.hydrodynamic_force;
  double torque = c.hydrodynamic_torque;
  for (int d = 0; d < 2; ++d) force[d] += rigid.mass * buoyancy_factor * in.gravity[d];
  const Vec2& x_c = rigid.state.centre;
  for (int p = 0; p < body.n_surface; ++p) {
    const Vec2& f = contact_force[p];
    force[0] += f[0];
    force[1] += f[1];
    torque += (body.position[p][0] - x_c[0]) * f[1] - (body.position[p][1] - x_c[1]) * f[0];
  }
  advance_newton_euler(dt_sub, force, torque, rigid);
  place_points(rigid, body);
}

}  // namespace

int advance_bodies(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                   const ContactForces& contact_forces, std::vector<BodyCoupling>& coupling,
                   std::vector<std::vector<Vec2>>& contact_work, std::vector<RigidBody>& rigid,
                   std::vector<MassSpringBody>& bodies) {
  const int n_sub =
      in.fixed_substeps > 0 ? in.fixed_substeps : substeps_for(bodies, in.dt, in.max_substep, in.spectral_workspace);
  const double dt_sub = in.dt / n_sub;
  contact_work.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) contact_work[b].resize(bodies[b].n_points());
  for (int k = 0; k < n_sub; ++k) {
    const double time_k = in.time + k*dt_sub;
    apply_swelling_schedules(swelling, time_k, bodies);  // L0 and M follow s(t), §1.8
    for (auto& forces : contact_work) std::fill(forces.begin(), forces.end(), Vec2{0.0, 0.0});
    contact_forces(bodies, time_k, contact_work);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      MassSpringBody& body = bodies[b];
      BodyCoupling& c = coupling[b];
      if (body.kind == BodyKind::rigid) {
        advance_rigid(in, dt_sub, c, contact_work[b], rigid[b], body);
        continue;
      }
      if (body.kind == BodyKind::prescribed) {
        rigid[b].state = rigid[b].prescribed.at(time_k + dt_sub);
        place_points(rigid[b], body);
        continue;
      }
      // M (1 - rho_f/rho_s) g: gravity on the body minus the buoyancy of the displaced fluid
      // (no gravity in the fluid, METHOD.md §2.6); with variant K the body's full mass M stays
      // on the left-hand side and the inner fluid's inertia arrives through F_int (§1.7).
      const double buoyancy_factor = 1.0 - in.fluid_density / body.density;
      for (int p = 0; p < body.n_points(); ++p)
        for (int d = 0; d < 2; ++d)
          c.external_force[p][d] = c.fluid_force[p][d] + c.inner_fluid_force[p][d] + contact_work[b][p][d] +
                                   body.mass[p] * buoyancy_factor * in.gravity[d];
      advance_symplectic_euler_in_place(body, dt_sub, c.external_force);  // rebuilt every sub-step above
    }
  }
  apply_swelling_schedules(swelling, in.time + in.dt, bodies);  // state at t^{n+1}
  return n_sub;
}

}  // namespace ibms
