// Shared set-up of the contact tests: wheels (D = 1, rho_s = 1, N_l = 20, equal masses) with
// no fluid, driven only by their springs and the DEM contacts, advanced with the production
// sub-step min(stable_substep, contact_substep) (ContactStepping::shared), or with the springs'
// stable sub-step and the contacts in the inner loop of contact_subcycle.hpp
// (ContactStepping::inner_loop, the production choice for groups of explicit mass-spring bodies).
// Restitution is measured on the centre-of-mass velocities along x:
// e = -(V_b - V_a)_after / (V_b - V_a)_before (a wall has V_b = 0).
// collide() also keeps the history from the first contact on (for the report's contact plot).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/body_substep.hpp"
#include "contact/contact_model.hpp"
#include "solid/mass_spring_body.hpp"
#include "solid/spring_forces.hpp"
#include "solid/stable_substep.hpp"

namespace ibms::test {

constexpr double contact_stiffness = 1e4;  // k_Dn [force/length^2]: delta_max ~ 0.6 % of D at v0 = 1
constexpr double impact_speed = 1.0;       // relative approach speed v0 [length/time]

// A wheel centred at `centre` moving with `velocity`, turned by `angle` about its centre (rim
// point 0 starts at `angle`), springs `stiffness_ratio` times stiffer than the contact (of
// stiffness `contact_k`), undamped.
inline MassSpringBody make_wheel(std::array<double, 2> centre, std::array<double, 2> velocity,
                                 double stiffness_ratio, double angle = 0.0, double contact_k = contact_stiffness) {
  BodyParameters spec;
  spec.centre = centre;
  spec.velocity = velocity;
  spec.diameter = 1.0;
  spec.n_surface_points = 20;
  spec.density = 1.0;
  spec.spring_stiffness = stiffness_ratio * contact_k;
  spec.spring_damping = 0.0;  // no internal dashpots: all dissipation is the contact's
  MassSpringBody body = build_wheel(spec);
  for (auto& x : body.position) {
    const double dx = x[0] - centre[0], dy = x[1] - centre[1];
    x = {centre[0] + std::cos(angle)*dx - std::sin(angle)*dy,
         centre[1] + std::sin(angle)*dx + std::cos(angle)*dy};
  }
  return body;
}

inline ContactModel make_contact_model(double restitution, double cds_radius_fraction = 0.05,
                                       double contact_k = contact_stiffness) {
  ContactModel model;
  model.stiffness = contact_k;
  model.restitution_coefficient = restitution;
  model.cds_radius_fraction = cds_radius_fraction;
  model.check();
  return model;
}

inline std::array<double, 2> centre_of_mass_velocity(const MassSpringBody& body) {
  std::array<double, 2> momentum{0.0, 0.0};
  for (int p = 0; p < body.n_points(); ++p)
    for (int c = 0; c < 2; ++c) momentum[c] += body.mass[p] * body.velocity[p][c];
  return {momentum[0] / body.total_mass(), momentum[1] / body.total_mass()};
}

enum class ContactStepping { shared, inner_loop };

// Kinetic energy of every point plus the springs' energy [energy/length].
inline double mechanical_energy(const std::vector<MassSpringBody>& bodies) {
  double energy = 0.0;
  for (const auto& body : bodies) energy += kinetic_energy(body) + spring_energy(body, body.length_scale());
  return energy;
}

struct CollisionRecord {
  std::vector<std::array<double, 2>> velocity_before, velocity_after;  // centre of mass, per body
  double max_overlap = 0.0;       // [length]
  int max_active = 0;             // most CDS pairs (or wall contacts) active at once [-]
  double contact_time = 0.0;      // [time]
  double substep = 0.0;           // [time]: the (outer) step
  int inner_steps = 1;            // inner contact steps per step (inner_loop) [-]
  double energy_before = 0.0, energy_after = 0.0;  // mechanical_energy [energy/length]
  double max_momentum_drift = 0.0;  // max |P(t) - P(0)| during the run, P = total momentum
  // Every sub-step from the first contact on: time since first contact [time], relative
  // centre-of-mass velocity along x over the approach speed (-1 before, e after) [-], largest
  // overlap [length].
  std::vector<std::array<double, 3>> history;
};

// Relative centre-of-mass velocity along x: second body minus first, or minus the first's (wall).
inline double relative_velocity_x(const std::vector<std::array<double, 2>>& v) {
  return v.size() > 1 ? v[1][0] - v[0][0] : -v[0][0];
}

// Runs until the bodies separate (relative centre-of-mass velocity away from each other) and have
// been apart for as long as they touched (so a re-contact would show): a soft wheel's rim point
// may rebound on its own while the body still approaches.
// implicit_springs: the springs take implicit Euler steps (no spring limit on the sub-step).
inline CollisionRecord collide(const ContactModel& model, const WallBox& box, std::vector<MassSpringBody> bodies,
                               bool implicit_springs = false, ContactStepping stepping = ContactStepping::shared) {
  CollisionRecord record;
  std::vector<ImplicitSpringSystem> implicit;
  ContactSubcycler subcycler;
  record.substep = contact_substep(model, bodies);
  double spring_substep = HUGE_VAL;
  if (!implicit_springs)
    for (const auto& body : bodies) spring_substep = std::min(spring_substep, stable_substep(body));
  const double outer = model.outer_step_fraction * spring_substep;
  const int n_inner = static_cast<int>(std::ceil(outer / record.substep * (1.0 - 1e-12)));
  if (stepping == ContactStepping::inner_loop && n_inner >= 2) {
    // As body_update.cpp plans it: a fraction of the springs' sub-step, the contact sub-step inside
    // it; where that gives one inner step (stiff springs), the shared sub-step.
    record.inner_steps = n_inner;
    record.substep = outer;
  } else {
    record.substep = std::min(record.substep, spring_substep);
  }
  record.energy_before = mechanical_energy(bodies);
  const auto total_momentum = [&] {
    std::array<double, 2> p{0.0, 0.0};
    for (const auto& body : bodies)
      for (int k = 0; k < body.n_points(); ++k)
        for (int c = 0; c < 2; ++c) p[c] += body.mass[k] * body.velocity[k][c];
    return p;
  };
  const std::array<double, 2> momentum0 = total_momentum();
  for (const auto& body : bodies) record.velocity_before.push_back(centre_of_mass_velocity(body));
  const std::vector<std::vector<std::array<double, 2>>> no_external = [&] {
    std::vector<std::vector<std::array<double, 2>>> zero;
    for (const auto& body : bodies) zero.emplace_back(body.n_points(), std::array<double, 2>{0.0, 0.0});
    return zero;
  }();
  double time_apart = 0.0;
  const double relative_before = relative_velocity_x(record.velocity_before);
  long first_contact = -1;
  for (long step = 0; step < 100000000; ++step) {
    const ContactStats stats =
        record.inner_steps > 1
            ? advance_bodies_inner_loop(model, box, record.substep, record.inner_steps, no_external, bodies,
                                        subcycler, /*continues=*/step > 0).stats
            : advance_bodies_substep(model, box, record.substep, no_external, bodies,
                                     implicit_springs ? &implicit : nullptr);
    const int n_active = stats.n_active_pairs + stats.n_wall_contacts;
    record.max_active = std::max(record.max_active, n_active);
    record.max_overlap = std::max(record.max_overlap, stats.max_overlap);
    const std::array<double, 2> momentum = total_momentum();
    record.max_momentum_drift = std::max(record.max_momentum_drift,
        std::hypot(momentum[0] - momentum0[0], momentum[1] - momentum0[1]));
    if (n_active > 0 && first_contact < 0) first_contact = step;
    if (first_contact >= 0) {
      std::vector<std::array<double, 2>> velocity;
      for (const auto& body : bodies) velocity.push_back(centre_of_mass_velocity(body));
      record.history.push_back({(step - first_contact + 1) * record.substep,
                                -relative_velocity_x(velocity) / relative_before, stats.max_overlap});
    }
    if (n_active > 0) {
      record.contact_time += record.substep;
      time_apart = 0.0;
    } else if (record.contact_time > 0.0) {
      time_apart += record.substep;
      std::vector<std::array<double, 2>> velocity;
      for (const auto& body : bodies) velocity.push_back(centre_of_mass_velocity(body));
      const bool separating = relative_velocity_x(velocity) * relative_before < 0.0;
      if (time_apart > record.contact_time && separating) break;
    }
  }
  for (const auto& body : bodies) record.velocity_after.push_back(centre_of_mass_velocity(body));
  record.energy_after = mechanical_energy(bodies);
  return record;
}

// e along x from the first body's centre-of-mass velocity and the second's (or a wall at rest).
inline double measured_restitution(const CollisionRecord& record) {
  return -relative_velocity_x(record.velocity_after) / relative_velocity_x(record.velocity_before);
}

// Relative change of the centres' kinetic energy over the collision, sum |V_b|^2 after over before
// minus 1 (the wheels' masses are equal, so they cancel) [-].
inline double centre_energy_change(const CollisionRecord& r) {
  double before = 0.0, after = 0.0;
  for (std::size_t b = 0; b < r.velocity_before.size(); ++b) {
    before += r.velocity_before[b][0]*r.velocity_before[b][0] + r.velocity_before[b][1]*r.velocity_before[b][1];
    after += r.velocity_after[b][0]*r.velocity_after[b][0] + r.velocity_after[b][1]*r.velocity_after[b][1];
  }
  return (after - before) / before;
}

}  // namespace ibms::test
