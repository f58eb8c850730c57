// Building a Simulation from a Scene: grid, wall motions, fluid solver, initial state.
#include "sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "scene/scene_schema.hpp"
#include "solid/spring_forces.hpp"

namespace ibms {

Grid grid_from_scene(const Scene& scene) {
  const DomainSpec& d = scene.domain;
  return Grid(d.cells_x, d.cells_y, d.length_x, d.length_y, d.periodic_x, d.periodic_y);
}

FluidBoundaries boundaries_from_scene(const Scene& scene) {
  const auto side = [](const WallSpec& w) {
    BoundarySide b;
    b.speed = w.speed;
    b.stop_time = w.stop_time;
    b.kind = w.kind;
    b.inflow.shape = w.profile;
    b.inflow.velocity = w.velocity;
    TimeFactor& f = b.inflow.factor;
    f.kind = w.time_factor;
    f.ramp_time = w.ramp_time;
    f.offset = w.factor_offset;
    f.amplitude = w.factor_amplitude;
    f.period = w.factor_period;
    return b;
  };
  FluidBoundaries bc;
  bc.periodic_x = scene.domain.periodic_x;
  bc.periodic_y = scene.domain.periodic_y;
  bc.left = side(scene.walls.left);
  bc.right = side(scene.walls.right);
  bc.bottom = side(scene.walls.bottom);
  bc.top = side(scene.walls.top);
  return bc;
}

namespace {

// The contact parameters of the scene's [contact] section.
ContactModel contact_model_of(const ContactSpec& spec) {
  ContactModel model;
  model.law = spec.model;
  model.stiffness = spec.stiffness;
  model.collision_steps = spec.collision_steps;
  model.restitution_coefficient = spec.restitution_coefficient;
  model.cds_radius = spec.cds_radius;
  model.cds_radius_fraction = spec.cds_radius_fraction;
  model.walls = spec.walls;
  model.centre_point = spec.centre_point;
  model.inner_step = spec.inner_step;
  model.outer_step_fraction = spec.outer_step_fraction;
  model.check();
  return model;
}

// The parameters of a body's point set from its [[bodies]] table.
BodyParameters body_parameters_of(const BodySpec& spec) {
  BodyParameters p;
  p.kind = spec.kind;
  p.centre = spec.centre;
  p.velocity = spec.velocity;
  p.angular_velocity = spec.angular_velocity;
  p.diameter = spec.diameter;
  p.n_surface_points = spec.n_surface_points;
  p.density = spec.density;
  p.spring_stiffness = spec.spring_stiffness;
  p.spring_damping = spec.spring_damping;
  p.restitution_coefficient = spec.restitution_coefficient;
  p.cross_springs = spec.cross_springs;
  p.mass_lumping = spec.mass_lumping;
  p.spring_integrator = spec.spring_integrator;
  return p;
}

// The motion of a rigid or prescribed body from its [[bodies]] table.
PrescribedMotion motion_of(const BodySpec& spec) {
  return {spec.centre,          spec.velocity,          spec.angular_velocity, spec.oscillation_amplitude,
          spec.angle_amplitude, spec.oscillation_period, spec.oscillation_phase};
}


}  // namespace

Simulation::Simulation(const Scene& scene)
    : scene_(scene),
      grid_(grid_from_scene(scene)),
      fluid_solver_(grid_, scene.fluid.kinematic_viscosity, boundaries_from_scene(scene),
                    FluidSchemes{.convection = scene.fluid.convection,
                                 .quadratic_wall = scene.fluid.wall_closure == FluidSpec::WallClosure::quadratic,
                                 .fft_planning = scene.run.fft_plans,
                                 .interpolation_time = scene.fluid.interpolation_time}),
      fluid_(fluid_solver_.make_state()),
      kernel_(scene.ibm.kernel),
      inner_fluid_inertia_(inner_fluid_inertia_of(scene.ibm.inner_fluid_inertia)),
      substep_planner_(scene_, bodies_, markers_, contact_model_, contact_box_, contact_inner_loop_) {
  fluid_solver_.initialise_faces(fluid_);  // fluid at rest: faces 0, projection is a no-op
  if (!has_bodies()) {
    set_instability_bounds();  // the driving speed: the fluid guard's speed scale
    coupling_ = make_coupling(scene_, grid_, kernel_, bodies_, markers_, rigid_);
    return;
  }
  // dV_l = h s_l (docs/method.md §3.6) and the kernel assume square cells.
  if (std::abs(grid_.dx() - grid_.dy()) > 1e-12 * grid_.dx())
    throw InputError(scene.source_file + ": domain: bodies need square cells (dx = dy), got dx = " +
                     std::to_string(grid_.dx()) + ", dy = " + std::to_string(grid_.dy()));
  for (const BodySpec& spec : scene.bodies) {
    bodies_.push_back(build_body(body_parameters_of(spec), scene.fluid.density));
    const bool mass_spring = spec.kind == BodySpec::Kind::mass_spring;
    rigid_.push_back(mass_spring ? RigidBody{} : rigid_body_of(bodies_.back(), motion_of(spec)));
    if (!mass_spring) place_points(rigid_.back(), bodies_.back());
    swelling_.emplace_back(spec.swelling, spec.diameter);
    const double largest = spec.swelling.enabled ? std::max(spec.diameter, spec.swelling.max_diameter) : spec.diameter;
    markers_.emplace_back(bodies_.back(), scene.ibm.sub_markers
                                              ? max_sub_marker_count(largest, spec.n_surface_points, grid_.dx())
                                              : static_cast<std::size_t>(spec.n_surface_points));
  }
  apply_swelling_schedules(swelling_, fluid_.time, bodies_);
  set_instability_bounds();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    markers_[b].slip_reference_speed =
        scene.bodies[b].reference_speed > 0.0 ? scene.bodies[b].reference_speed : instability_.driving_speed;
  coupling_ = make_coupling(scene_, grid_, kernel_, bodies_, markers_, rigid_);
  if (scene.contact.enabled()) wire_contacts();
  // Variant K (both loads): I_T at t = 0 (region X^0, velocity u^0), the first "previous" value.
  if (inner_fluid_inertia_ != &no_inner_fluid_inertia)
    sample_inner_fluid_momentum(grid_, fluid_, bodies_, markers_);
}

void Simulation::record_contacts(double seconds, const ContactStats& found, long inner_steps) {
#if defined(_OPENMP)
#pragma omp critical(ibms_contact_stats)
#endif
  {
    timers_.add(Stage::contacts, seconds, 1);
    stats_.total_pair_checks += found.n_pair_checks;
    stats_.total_contact_inner_steps += inner_steps;
    stats_.last_contact_stats.include(found);
  }
}

// The contact seams of body_update.hpp: DEM forces every sub-step (or the inner loop), their
// figures merged per step.
void Simulation::wire_contacts() {
  contact_model_ = contact_model_of(scene_.contact);
  contact_box_ = WallBox{{grid_.origin_x, grid_.origin_y}, {grid_.length_x, grid_.length_y},
                         {grid_.periodic_x, grid_.periodic_y}};
  for (Side s : {Side::left, Side::right, Side::bottom, Side::top}) {
    const SideKind k = boundaries().kind(grid_, s);
    contact_box_.open[static_cast<int>(s)] = k == SideKind::inflow || k == SideKind::outflow;
  }
  // Runs on several threads at once (one per body group): the forces of each group are its own;
  // the shared totals are maxima and integer sums (order-independent), updated under a lock.
  contact_forces_ = [this](const std::vector<MassSpringBody>& bodies, const BodySet& members, double /*time*/,
                           std::vector<std::vector<Vec2>>& forces) {
    const auto start = std::chrono::steady_clock::now();
    const ContactStats found = add_contact_forces(contact_model_, bodies, contact_box_, forces, members);
    record_contacts(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), found, 0);
  };
  if (scene_.contact.time_stepping != ContactSpec::TimeStepping::inner_loop) return;
  contact_inner_loop_ = [this](std::vector<MassSpringBody>& bodies, const BodySet& members, double dt_outer,
                               int n_inner, const std::vector<std::vector<Vec2>>& frozen_force, bool continues,
                               const std::vector<double>& diameter_rate) {
    thread_local ContactSubcycler subcycler;  // this thread's neighbour list and scratch
    const auto start = std::chrono::steady_clock::now();
    const ContactSubcycleResult result = subcycler.advance(contact_model_, contact_box_, dt_outer, n_inner,
                                                           frozen_force, members, bodies, continues, diameter_rate);
    record_contacts(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), result.stats,
                    result.inner_steps);
    return result.work;
  };
}

void Simulation::set_instability_bounds() {
  double speed = speed_scale();
  const double gravity = std::hypot(scene_.fluid.gravity[0], scene_.fluid.gravity[1]);
  const double diagonal = std::hypot(grid_.length_x, grid_.length_y);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodySpec& spec = scene_.bodies[b];
    const MassSpringBody& body = bodies_[b];
    if (spec.swelling.enabled) speed = std::max(speed, spec.swelling.rate);
    if (body.kind == BodyKind::prescribed) {
      const double w_osc = spec.oscillation_period > 0 ? 2 * pi / spec.oscillation_period : 0.0;
      speed = std::max(speed, std::hypot(spec.velocity[0], spec.velocity[1]) +
                                  std::hypot(spec.oscillation_amplitude[0], spec.oscillation_amplitude[1]) * w_osc +
                                  0.5 * body.diameter * (std::abs(spec.angular_velocity) + std::abs(spec.angle_amplitude) * w_osc));
    } else {
      speed = std::max(speed, std::sqrt(2.0 * std::abs(1.0 - scene_.fluid.density / body.density) * gravity * diagonal));
    }
  }
  // A scene with nothing driving it still needs a non-zero scale (round-off moves the bodies):
  // crossing a thousandth of the box in the whole run.
  instability_.driving_speed = std::max(speed, 1e-3 * diagonal / scene_.run.end_time);
  instability_.body_energy_scale.clear();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodySpec& spec = scene_.bodies[b];
    const double largest = spec.swelling.enabled ? std::max(spec.diameter, spec.swelling.max_diameter) : spec.diameter;
    const double mass = bodies_[b].density * pi * largest * largest / 4.0;
    instability_.body_energy_scale.push_back(0.5 * mass * instability_.driving_speed * instability_.driving_speed +
                                 spring_energy(bodies_[b], bodies_[b].length_scale()));
  }
}

SubstepGroups& Simulation::substep_groups(double dt) {
  contact_model_ = contact_model_.for_fluid_step(dt);
  return substep_planner_.plan_step(dt);
}

std::vector<std::string> Simulation::stage_names() const {
  std::vector<std::string> stages;
  if (has_bodies()) stages.push_back("schedules (wall velocities, swelling)");
  else stages.push_back("schedules (wall velocities)");
  const char* convection = convection_name(fluid_solver_.schemes().convection);
  stages.push_back(std::string("predictor (AB2 ") + convection +
                   " convection, Crank-Nicolson diffusion by DST Helmholtz" +
                   (scene_.fluid.wall_closure == FluidSpec::WallClosure::quadratic
                        ? ", quadratic wall closure by defect correction: one sweep from the explicit estimate up "
                          "to nu dt/h^2 = " +
                              fmt::format("{:g}", fluid_solver_.schemes().single_sweep_viscous_number) +
                              ", above it 2 sweeps from u^n up to 4/3, " +
                              std::to_string(FluidSolver::wall_closure_sweeps) + " beyond)"
                        : ")"));
  if (const std::string forcing = coupling_->forcing_stage(); !forcing.empty()) stages.push_back(forcing);
  stages.push_back("projection (momentum interpolation, DCT/FFT Poisson)");
  if (const std::string corrections = coupling_->correction_stage(); !corrections.empty())
    stages.push_back(corrections);
  if (has_bodies()) {
    stages.push_back("fluid reaction on the rim points");
    switch (scene_.ibm.inner_fluid_inertia) {
      case IbmSpec::InnerFluidInertia::kempe:
        stages.push_back("inner-fluid inertia (variant K: exact triangle-cell overlaps, Reynolds-transport form, a third "
                         "of each triangle's force to each of its vertices)");
        break;
      case IbmSpec::InnerFluidInertia::kempe_by_mass:
        stages.push_back("inner-fluid inertia (variant K: exact triangle-cell overlaps, Reynolds-transport form, the "
                         "body's force and torque laid on its points as a rigid motion of their masses)");
        break;
      case IbmSpec::InnerFluidInertia::none: stages.push_back("inner-fluid inertia off (variant A)"); break;
    }
    std::string kinds;
    if (scene_.has_kind(BodySpec::Kind::mass_spring))
      kinds += "mass-spring: symplectic Euler sub-steps, or implicit Euler for stiff springs (springs, buoyant gravity, "
               "swelling); ";
    if (scene_.has_kind(BodySpec::Kind::rigid)) kinds += "rigid: Newton-Euler (force, torque, buoyant gravity); ";
    if (scene_.has_kind(BodySpec::Kind::prescribed)) kinds += "prescribed: scene motion; ";
    stages.push_back("hydrodynamic force and torque on each body");
    const bool per_group = scene_.run.solid_substeps == RunSpec::SolidSubsteps::per_group;
    stages.push_back("bodies (" + kinds + "contact hook" +
                     (per_group ? "; each group of bodies that may touch within the step at its own sub-step)"
                                : "; all bodies at the smallest sub-step)"));
    const std::string law = scene_.contact.model == ContactSpec::Model::collision_time
                                ? fmt::format("collision-time law: k and c per contact from m_eff and e_D, T_c = {:g} "
                                              "fluid steps", scene_.contact.collision_steps)
                                : "linear law at k_Dn";
    if (has_contacts())
      stages.push_back(scene_.contact.time_stepping == ContactSpec::TimeStepping::inner_loop
                           ? "  contacts (DEM spring-dashpots on CDS, " + law +
                                 ", walls; groups of explicit mass-spring bodies: inner loop over the points near a "
                                 "contact at " +
                                 (scene_.contact.inner_step == ContactSpec::InnerStep::listed_pairs
                                      ? fmt::format("t_c / {:g} of the fastest mode its listed CDS pairs can form",
                                                    contact_model_.steps_per_contact)
                                      : std::string("the group's contact sub-step")) +
                                 fmt::format(", springs and fluid held over outer steps of {:g} (1/{:g}) of the springs' "
                                             "sub-step)", contact_model_.outer_step_fraction,
                                             1.0 / contact_model_.outer_step_fraction)
                           : "  contacts (DEM spring-dashpots on CDS, " + law + ", every sub-step; walls)");
    if (has_pair_search()) stages.push_back("  pair search (CDS: body-box broad phase, cell list in periodic boxes; every sub-step)");
  }
  stages.push_back("diagnostics");
  if (scene_.run.steady_tolerance > 0) stages.push_back("steady-state stop");
  return stages;
}

}  // namespace ibms
