// Sub-stepped mass-spring update of the bodies, docs/method.md §5.3 (see body_update.hpp).
#include "sim/bodies/body_update.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "contact/contact_subcycle.hpp"
#include "solid/stable_substep.hpp"
#include "solid/symplectic_euler.hpp"

namespace ibms {

void no_contact_forces(const std::vector<MassSpringBody>&, const BodySet&, double, std::vector<std::vector<Vec2>>&) {}

void apply_swelling_schedules(const std::vector<SwellingSchedule>& swelling, double time,
                              std::vector<MassSpringBody>& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (swelling[b].enabled) apply_swelling(bodies[b], swelling[b].diameter(time));
}

void SubstepGroups::list_members() {
  const std::size_t n_groups = max_substep.size();
  member_start.assign(n_groups + 1, 0);
  const auto listed = [n_groups](int g) { return g >= 0 && static_cast<std::size_t>(g) < n_groups; };
  for (const int g : group_of)
    if (listed(g)) ++member_start[g + 1];
  for (std::size_t g = 0; g < n_groups; ++g) member_start[g + 1] += member_start[g];
  member_list.resize(member_start.back());
  thread_local std::vector<int> cursor;
  cursor.assign(member_start.begin(), member_start.end() - 1);
  for (std::size_t b = 0; b < group_of.size(); ++b)
    if (listed(group_of[b])) member_list[cursor[group_of[b]]++] = static_cast<int>(b);
}

bool uses_implicit_springs(const MassSpringBody& body, double dt, double spring_substep) {
  if (body.kind != BodyKind::mass_spring || body.springs.empty()) return false;
  switch (body.integrator) {
    case SpringIntegrator::explicit_euler: return false;
    case SpringIntegrator::implicit_euler: return true;
    case SpringIntegrator::automatic: return dt > implicit_springs_above_substeps * spring_substep;
  }
  return false;
}

SpringStepping spring_stepping(const MassSpringBody& body, double dt, SpectralWorkspace& scratch) {
  const bool forced_implicit = body.integrator == SpringIntegrator::implicit_euler;
  const double substep = forced_implicit ? HUGE_VAL : stable_substep(body, /*safety=*/0.5, scratch);
  if (uses_implicit_springs(body, dt, substep)) return {true, HUGE_VAL};
  return {false, substep};
}

namespace {

// Rigid body: total force and torque about X_c of the frozen hydrodynamic load, this sub-step's
// contact forces on the rim points and the buoyancy-corrected weight; one Newton-Euler step.
void advance_rigid(const SolidStepInputs& in, double dt_sub, const BodyCoupling& c,
                   const std::vector<Vec2>& contact_force, RigidBody& rigid, MassSpringBody& body) {
  const Vec2 weight = body.buoyant_weight(rigid.mass, in.fluid_density, in.gravity);
  Vec2 force = c.hydrodynamic_force;
  double torque = c.hydrodynamic_torque;
  for (int d = 0; d < 2; ++d) force[d] += weight[d];
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

namespace {

// The force on every point of a mass-spring body other than its springs, F_f + F_int +
// M (1 - rho_f/rho_s) g + contact (null: none, the inner loop adds the contacts), into
// c.external_force.
void external_force(const SolidStepInputs& in, const std::vector<Vec2>* contact, const MassSpringBody& body,
                    BodyCoupling& c) {
  // With variant K the body's full mass M stays on the left-hand side and the inner fluid's
  // inertia arrives through F_int (§1.7).
  for (int p = 0; p < body.n_points(); ++p) {
    const Vec2 weight = body.buoyant_weight(body.mass[p], in.fluid_density, in.gravity);
    for (int d = 0; d < 2; ++d)
      c.external_force[p][d] = c.fluid_force[p][d] + c.inner_fluid_force[p][d] +
                               (contact != nullptr ? (*contact)[p][d] : 0.0) + weight[d];
  }
}

// One group of mass-spring bodies with explicit springs in n_sub outer sub-steps, the contacts in
// the inner loop (n_inner inner steps per sub-step). frozen is scratch (the caller's contact_work
// arrays, one per body): the force on each point other than springs and contacts.
void advance_group_inner_loop(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                              const ContactInnerLoop& inner_loop, const BodySet& members, int n_sub, int n_inner,
                              std::vector<BodyCoupling>& coupling, std::vector<std::vector<Vec2>>& frozen,
                              std::vector<double>& diameter_rate, std::vector<MassSpringBody>& bodies,
                              double& contact_energy) {
  const double dt_sub = in.dt / n_sub;
  for (int k = 0; k < n_sub; ++k) {
    const double time_k = in.time + k*dt_sub;
    for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
      const std::size_t b = members.at(i);
      if (swelling[b].enabled) apply_swelling(bodies[b], swelling[b].diameter(time_k));  // L0, M follow s(t), §1.8
      diameter_rate[b] =
          swelling[b].enabled ? (swelling[b].diameter(time_k + dt_sub) - swelling[b].diameter(time_k)) / dt_sub : 0.0;
      external_force(in, nullptr, bodies[b], coupling[b]);
      std::copy(coupling[b].external_force.begin(), coupling[b].external_force.end(), frozen[b].begin());
    }
    contact_energy += inner_loop(bodies, members, dt_sub, n_inner, frozen, /*continues=*/k > 0, diameter_rate);
  }
}

// One group (members) from t^n to t^n + dt in n_sub shared sub-steps.
void advance_group(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                   const ContactForces& contact_forces, const BodySet& members, const std::vector<char>& implicit_of_body,
                   std::vector<ImplicitSpringSystem>& implicit, int n_sub,
                   std::vector<BodyCoupling>& coupling, std::vector<std::vector<Vec2>>& contact_work,
                   std::vector<RigidBody>& rigid, std::vector<MassSpringBody>& bodies, double& contact_energy) {
  const double dt_sub = in.dt / n_sub;
  for (int k = 0; k < n_sub; ++k) {
    const double time_k = in.time + k*dt_sub;
    for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
      const std::size_t b = members.at(i);
      if (swelling[b].enabled) apply_swelling(bodies[b], swelling[b].diameter(time_k));  // L0, M follow s(t), §1.8
      std::fill(contact_work[b].begin(), contact_work[b].end(), Vec2{0.0, 0.0});
    }
    // Evaluated in every group, also in one that cannot touch anything by the reach test: a
    // contact the test did not foresee still acts (at that group's sub-step), and the walls and
    // the pairs inside a group of one cost little.
    contact_forces(bodies, members, time_k, contact_work);
    for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
      const std::size_t b = members.at(i);
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
      external_force(in, &contact_work[b], body, c);
      if (implicit_of_body[b]) implicit[b].advance(body, dt_sub, c.external_force);  // no spring limit
      else advance_symplectic_euler_in_place(body, dt_sub, c.external_force);  // rebuilt every sub-step above
    }
    // Work of the contact forces on every member over the sub-step, F . U^{k+1} dt_sub (the
    // displacement the position update made), prescribed bodies included.
    for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
      const std::size_t b = members.at(i);
      for (int p = 0; p < bodies[b].n_points(); ++p)
        contact_energy += dt_sub * (contact_work[b][p][0] * bodies[b].velocity[p][0] +
                                    contact_work[b][p][1] * bodies[b].velocity[p][1]);
    }
  }
}

}  // namespace

namespace {

// The bodies of group g (global mode, g = -1: every body) in the step.
BodySet group_bodies(const SubstepGroups& groups, int g) { return g < 0 ? BodySet{} : groups.group_members(g); }

// Decides the spring integrator of group g's mass-spring bodies (groups.implicit_of_body) and
// returns the sub-steps the group needs in this step (0: no members). inner_substeps: the inner contact steps per
// sub-step when the group takes the inner loop (its sub-step is then its springs' alone), else 0.
int group_substeps(const SolidStepInputs& in, SubstepGroups& groups, int g, const std::vector<MassSpringBody>& bodies,
                   SpectralWorkspace& scratch, int& inner_substeps) {
  inner_substeps = 0;
  const BodySet members = group_bodies(groups, g);
  groups.implicit_of_body.resize(bodies.size());
  const double contact_dt = g < 0 ? in.max_substep : groups.max_substep[g];
  double spring_dt = HUGE_VAL;
  int n_members = 0;
  bool inner_loop_fits = static_cast<bool>(groups.inner_loop) && std::isfinite(contact_dt);
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const std::size_t b = members.at(i);
    ++n_members;
    const SpringStepping springs = spring_stepping(bodies[b], in.dt, scratch);
    groups.implicit_of_body[b] = springs.implicit ? 1 : 0;
    spring_dt = std::min(spring_dt, springs.substep);
    // Rigid and prescribed bodies move all their points at once; implicit springs are not slow.
    if (bodies[b].kind != BodyKind::mass_spring || groups.implicit_of_body[b]) inner_loop_fits = false;
  }
  if (n_members == 0) return 0;
  if (in.fixed_substeps > 0) return in.fixed_substeps;
  const auto substeps = [&](double span, double limit) {
    if (!(limit > 0.0)) throw std::runtime_error("advance_bodies: non-positive stable sub-step");
    return std::max(1, static_cast<int>(std::ceil(span / limit * (1.0 - 1e-12))));
  };
  if (inner_loop_fits) {
    // Only where it pays: springs slower than the contact (stiff bodies keep the shared sub-step).
    const int n_outer = substeps(in.dt, groups.outer_step_fraction * spring_dt);
    const int n_inner = substeps(in.dt / n_outer, contact_dt);
    if (n_inner >= 2) {
      inner_substeps = n_inner;
      return n_outer;
    }
  }
  return substeps(in.dt, std::min(contact_dt, spring_dt));
}

// Group numbers to visit: -1 alone in the global mode, else 0 .. n_groups - 1.
int first_group(const SubstepGroups& groups, const std::vector<MassSpringBody>& bodies) {
  return groups.group_of.size() == bodies.size() ? 0 : -1;
}
int end_group(const SubstepGroups& groups, const std::vector<MassSpringBody>& bodies) {
  return groups.group_of.size() == bodies.size() ? static_cast<int>(groups.max_substep.size()) : 0;
}

void record(const BodySet& members, int n_sub, std::vector<int>& substeps_of_body, SolidStepCount& count) {
  count.max_substeps = std::max(count.max_substeps, n_sub);
  for (std::size_t i = 0; i < members.count(substeps_of_body.size()); ++i) {
    substeps_of_body[members.at(i)] = n_sub;
    count.body_substeps += n_sub;
  }
}

}  // namespace

SolidStepCount count_substeps(const SolidStepInputs& in, SubstepGroups& groups,
                              const std::vector<MassSpringBody>& bodies) {
  SpectralWorkspace local;
  SpectralWorkspace& scratch = in.spectral_workspace != nullptr ? *in.spectral_workspace : local;
  SolidStepCount count;
  groups.substeps_of_body.assign(bodies.size(), 0);
  groups.group_substeps.reserve(bodies.size());  // at most one group per body: sized once
  groups.group_substeps.clear();
  groups.group_inner_substeps.reserve(bodies.size());
  groups.group_inner_substeps.clear();
  if (first_group(groups, bodies) == 0) groups.list_members();
  for (int g = first_group(groups, bodies); g < end_group(groups, bodies); ++g) {
    int inner = 0;
    groups.group_substeps.push_back(group_substeps(in, groups, g, bodies, scratch, inner));
    groups.group_inner_substeps.push_back(inner);
    record(group_bodies(groups, g), groups.group_substeps.back(), groups.substeps_of_body, count);
  }
  return count;
}

SolidStepCount advance_bodies(const SolidStepInputs& in, const std::vector<SwellingSchedule>& swelling,
                              const ContactForces& contact_forces, SubstepGroups& groups,
                              std::vector<BodyCoupling>& coupling, std::vector<std::vector<Vec2>>& contact_work,
                              std::vector<RigidBody>& rigid, std::vector<MassSpringBody>& bodies) {
  std::vector<ImplicitSpringSystem> local_implicit;
  std::vector<ImplicitSpringSystem>& implicit = in.implicit_systems != nullptr ? *in.implicit_systems : local_implicit;
  implicit.resize(bodies.size());
  contact_work.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) contact_work[b].resize(bodies[b].n_points());
  // Plan, in group order: the sub-steps of each group and the spring integrator of each body.
  const SolidStepCount count = count_substeps(in, groups, bodies);
  const int first = first_group(groups, bodies), end = end_group(groups, bodies);
  groups.group_work.reserve(bodies.size());
  // Groups cannot touch one another within the step (contact_model.hpp): each advances over the
  // whole step with its own sub-step, independently, so on several threads (one group
  // per thread at a time). A group's result does not depend on the thread that ran it, and
  // the per-group contact work is summed in group order afterwards: bitwise the same for any
  // thread count. Exceptions (a blow-up) are caught per group; the lowest group's is rethrown.
  const int n_groups = end - first;
  groups.group_work.assign(n_groups, 0.0);
  groups.diameter_rate.resize(bodies.size());  // each group writes its members' entries
  std::exception_ptr error;
  int error_group = n_groups;
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic, 1) if (n_groups > 1)
#endif
  for (int k = 0; k < n_groups; ++k) {
    if (groups.group_substeps[k] == 0) continue;
    const BodySet mask = group_bodies(groups, first < 0 ? -1 : first + k);
    try {
      if (groups.group_inner_substeps[k] > 0)
        advance_group_inner_loop(in, swelling, groups.inner_loop, mask, groups.group_substeps[k],
                                 groups.group_inner_substeps[k], coupling, contact_work, groups.diameter_rate, bodies,
                                 groups.group_work[k]);
      else
        advance_group(in, swelling, contact_forces, mask, groups.implicit_of_body, implicit, groups.group_substeps[k],
                      coupling, contact_work, rigid, bodies, groups.group_work[k]);
    } catch (...) {
#if defined(_OPENMP)
#pragma omp critical(ibms_group_error)
#endif
      if (k < error_group) {
        error_group = k;
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  groups.contact_work = 0.0;
  for (double work : groups.group_work) groups.contact_work += work;
  apply_swelling_schedules(swelling, in.time + in.dt, bodies);  // state at t^{n+1}
  return count;
}

}  // namespace ibms
