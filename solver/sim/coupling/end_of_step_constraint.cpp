// The end-of-step constraint (end_of_step_constraint.hpp, docs/method.md §3.7).
#include "sim/coupling/end_of_step_constraint.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scene/scene_schema.hpp"

namespace ibms {

EndOfStepConstraint::EndOfStepConstraint(const Scene& scene, const Grid& grid, KernelKind kernel,
                                         const std::vector<MassSpringBody>& bodies, std::vector<BodyCoupling>& markers,
                                         std::vector<RigidBody>& rigid)
    : kernel_(kernel),
      kernel_name_(scene_schema::name_of(scene.ibm.kernel)),
      passes_(scene.ibm.forcing_passes),
      slip_tolerance_(scene.ibm.slip_tolerance),
      max_products_(scene.ibm.max_coupling_iterations),
      on_faces_(scene.ibm.constrained_velocity == IbmSpec::ConstrainedVelocity::faces),
      has_mass_spring_(scene.has_kind(BodySpec::Kind::mass_spring)),
      fluid_density_(scene.fluid.density),
      gravity_(scene.fluid.gravity) {
  for (std::size_t b = 0; b < bodies.size(); ++b) markers[b].given_motion = bodies[b].kind == BodyKind::prescribed;
  // Rigid bodies respond in the marker system with their mass less the inner fluid's (which the
  // inner-fluid term gives back as rho_f V dU/dt while the inner fluid moves with the body); a body
  // no heavier than the fluid there, or ibm.rigid_response = "virtual_mass", moves with the virtual
  // mass C_V rho_f V instead (Schwarz, Kempe & Froehlich 2015).
  const bool inner = scene.ibm.inner_fluid_inertia != IbmSpec::InnerFluidInertia::none;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].kind != BodyKind::rigid) continue;
    RigidBody& r = rigid[b];
    const double inner_mass = inner ? scene.fluid.density * bodies[b].solid_area() : 0.0;
    const double diameter = scene.bodies[b].diameter;
    if (scene.ibm.rigid_response == IbmSpec::RigidResponse::implicit && r.mass - inner_mass > 0.0) {
      markers[b].response_mass = r.mass - inner_mass;
      markers[b].response_inertia = r.moment_of_inertia - inner_mass * diameter * diameter / 8.0;
      markers[b].body_velocity_change.assign(markers[b].marker.capacity(), Vec2{0.0, 0.0});
      markers[b].body_velocity_change.resize(markers[b].marker.size());
      r.virtual_mass = r.virtual_inertia = 0.0;
      has_responding_rigid_ = true;
      continue;
    }
    r.virtual_mass = scene.ibm.virtual_mass_coefficient * scene.fluid.density * bodies[b].solid_area();
    r.virtual_inertia = r.virtual_mass * diameter * diameter / 8.0;
  }
  arrays_.slip_increment_x = CellField(grid);
  arrays_.slip_increment_y = CellField(grid);
  arrays_.force_cell_x = CellField(grid);
  arrays_.force_cell_y = CellField(grid);
  arrays_.force_face_x = FaceField::x_faces(grid);
  arrays_.force_face_y = FaceField::y_faces(grid);
  std::size_t unknowns = 0;
  for (const BodyCoupling& c : markers) unknowns += 2 * c.marker.capacity();
  arrays_.work.reserve(unknowns);
  arrays_.work.reserve_potentials(grid);
  // The blocks' drift: as given, or "auto" from the blocks' sizes against the grid's (marker_preconditioner.hpp).
  double block_unknowns_squared = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (may_take_own_operator(markers[b])) {
      const double n = 2.0 * static_cast<double>(markers[b].marker.capacity());
      block_unknowns_squared += n * n;
    }
  preconditioner_drift_ = scene.ibm.preconditioner_drift == IbmSpec::preconditioner_drift_auto
                              ? automatic_preconditioner_drift(block_unknowns_squared, grid.nx * grid.ny)
                              : scene.ibm.preconditioner_drift;
  arrays_.preconditioner.reserve(markers, scene.fluid.density, preconditioner_drift_);
  arrays_.response_systems.resize(bodies.size());
  rim_response_ = scene.ibm.rim_preconditioner == IbmSpec::RimPreconditioner::response;
  if (rim_response_) arrays_.preconditioner.attach_rim_systems(&arrays_.response_systems);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].kind != BodyKind::mass_spring) continue;
    markers[b].body_velocity_change.assign(markers[b].marker.capacity(), Vec2{0.0, 0.0});
    markers[b].body_velocity_change.resize(markers[b].marker.size());
    markers[b].response_work.assign(2 * bodies[b].n_points(), 0.0);
  }
  balanced_ = {&arrays_.force_cell_x, &arrays_.force_cell_y, &arrays_.force_face_x, &arrays_.force_face_y};
}

// The previous step's forces inside the Crank-Nicolson solve (when the markers are the same;
// otherwise direct forcing as Uhlmann), then the step's force on cells and faces for the projection.
void EndOfStepConstraint::predict(const CouplingStep& step) {
  const Grid& grid = step.solver.grid();
  CellField& star_x = step.solver.velocity_star_x();
  CellField& star_y = step.solver.velocity_star_y();
  { auto t = step.timers.time(Stage::predictor); step.solver.predict_explicit(step.fluid, step.dt); }  // u~_e
  bool predicted = false;
  {
    auto t = step.timers.time(Stage::ib_forcing);
    // The markers stay put until the bodies move at the end of the step: their stencils are mapped
    // once for the step's spreads, the marker solve and its preconditioner (hold).
    for (BodyCoupling& c : step.markers) map_face_stencils(grid, kernel_, c.marker, c.face_stencils);
    predicted = spread_previous_forces(grid, step.dt, step.markers, star_x, star_y);  // u~_e + dt S F^{n-1}
  }
  if (!predicted) force_markers(step, kernel_, passes_);                                       // u~_e + dt f
  {
    auto t = step.timers.time(Stage::ib_forcing);
    NoSlipArrays& a = arrays_;
    spread_step_forces(grid, step.dt, step.markers, a.force_cell_x, a.force_cell_y, a.force_face_x,
                       a.force_face_y);  // dt S F, dt S_f F for the faces
    // Under the face constraint the cells take the force as the mean of its face values, as they
    // take the pressure gradient.
    if (on_faces_)
      cell_forces_from_faces(grid, a.force_face_x, a.force_face_y, a.force_cell_x, a.force_cell_y, star_x,
                             star_y);  // dt A S_f F
  }
  { auto t = step.timers.time(Stage::predictor); step.solver.complete_prediction(step.fluid, step.dt); }  // u~ with f
}

// The targets at the end of the step. A prescribed body's points move at their velocity of t^{n+1}
// from the motion law: its change since U^n joins the target, so that the force does not lag the
// motion by a step. A mass-spring body: the backward-Euler step over dt without the fluid, from
// x^n, U^n with its springs, dashpots and buoyant weight, factorised for the response; its velocity
// change joins the target (the rim velocity at the end of the step).
bool EndOfStepConstraint::prepare_body_responses(const CouplingStep& step) {
  bool any = false;
  for (std::size_t b = 0; b < step.bodies.size(); ++b) {
    BodyCoupling& c = step.markers[b];
    if (step.bodies[b].kind == BodyKind::prescribed) {
      const MassSpringBody& body = step.bodies[b];
      const RigidBody& motion = step.rigid[b];
      point_velocities(motion, motion.prescribed.at(step.time_n + step.dt), c.external_force);  // U^{n+1}
      for (int p = 0; p < body.n_points(); ++p)
        for (int d = 0; d < 2; ++d) c.external_force[p][d] -= body.velocity[p][d];
      add_point_velocity_change(body, c.external_force, c);
      continue;
    }
    if (c.body_velocity_change.empty()) continue;
    const MassSpringBody& body = step.bodies[b];
    any = true;
    if (c.response_mass > 0.0) {  // a rigid body: its buoyant weight over the step, its arms
      rigid_arms(body, c, c.rigid_arm);
      const Vec2 weight = body.buoyant_weight(step.rigid[b].mass, fluid_density_, gravity_);
      for (Vec2& u : c.target_velocity)
        for (int d = 0; d < 2; ++d) u[d] += step.dt * weight[d] / c.response_mass;
      continue;
    }
    for (int p = 0; p < body.n_points(); ++p)
      c.external_force[p] = body.buoyant_weight(body.mass[p], fluid_density_, gravity_);
    arrays_.response_systems[b].velocity_change(body, step.dt, c.external_force);  // dU without the fluid
    c.body_velocity_change.resize(c.marker.size());  // sub-markers come and go: capacity reserved
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) c.target_velocity[l][d] += rim_to_marker(c, l, body.n_surface, c.external_force, d);
  }
  return any;
}

// Force corrections projected with the pressure until no-slip holds at every marker.
CouplingWork EndOfStepConstraint::hold(const CouplingStep& step) {
  auto t = step.timers.time(Stage::ib_forcing);
  const Grid& grid = step.solver.grid();
  FluidState& fluid = step.fluid;
  const WallVelocities walls = wall_velocities_at(step.solver.boundaries(), step.time_n + step.dt);
  const bool responds = prepare_body_responses(step);
  // -(M + dt D + dt^2 S)^{-1} rho_f dV (dt F) on the rim points of body b: a marker's impulse goes to
  // its edge's end points, and the change comes back to it, with the weights (1 - w, w) (§3.6).
  std::vector<BodyCoupling>& markers = step.markers;
  // Two captures: std::function keeps them in place, without allocating.
  const BodyResponse response = [this, &step](std::size_t b, const std::vector<Vec2>& impulse,
                                              std::vector<Vec2>& change) {
    BodyCoupling& c = step.markers[b];
    if (c.response_mass > 0.0) {
      rigid_response(fluid_density_, c, c.rigid_arm, c.marker_volume, c.marker_fraction_work, impulse, change);
      return;
    }
    std::vector<double>& x = c.response_work;
    std::fill(x.begin(), x.end(), 0.0);
    const int n_rim = step.bodies[b].n_surface;
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) marker_to_rim(c, l, n_rim, -fluid_density_ * c.marker_volume[l] * impulse[l][d], d, x);
    arrays_.response_systems[b].response(x);
    for (std::size_t l = 0; l < c.marker.size(); ++l)
      for (int d = 0; d < 2; ++d) change[l][d] = rim_to_marker(c, l, n_rim, x, d);
  };
  NoSlipArrays& a = arrays_;
  const NoSlipResult result =
      hold_no_slip(grid, kernel_, walls, step.dt, slip_tolerance_, on_faces_, on_faces_, max_products_, step.solver,
                   fluid, markers, a.slip_increment_x, a.slip_increment_y, a.force_face_x, a.force_face_y, a.work,
                   responds ? response : BodyResponse{}, &a.preconditioner);
  keep_forces(markers);
  return {result.products, result.max_change};
}

void EndOfStepConstraint::measure_slip_at_end(const FluidSolver& solver, const FluidState& fluid,
                                              std::vector<BodyCoupling>& markers) const {
  // Cells and faces differ by the momentum interpolation's dt (mean(G_c) - G_f) p (§2.3).
  const Grid& grid = solver.grid();
  const WallVelocities walls = wall_velocities_at(solver.boundaries(), fluid.time);  // t^{n+1}
  if (on_faces_)
    measure_slip(grid, kernel_, walls, fluid.velocity_x, fluid.velocity_y, markers);
  else
    measure_face_slip(grid, kernel_, walls, fluid.velocity_face_x, fluid.velocity_face_y, markers);
}

std::string EndOfStepConstraint::forcing_stage() const {
  return "immersed-boundary forcing (" + kernel_name_ +
         ", no_slip coupling: the previous step's forces inside the Crank-Nicolson solve; first step " +
         std::to_string(passes_) + " pass(es); target = marker velocity minus swelling part)";
}

std::string EndOfStepConstraint::correction_stage() const {
  return "no-slip corrections (force corrections projected until the slip at t^{n+1} <= " +
         fmt::format("{:g}", slip_tolerance_) +
         " U_ref; GMRES preconditioned body by body: " +
         (on_faces_ ? fmt::format("prescribed and responding rigid bodies by their own operator (lattice Green's "
                                  "function, built again when their markers drift {:g} cells), mass-spring rims {}, "
                                  "others by J S and the rim's leak",
                                  preconditioner_drift_,
                                  rim_response_ ? "by their response with the diagonal of J_f S_f (Woodbury)"
                                                : "by the identity")
                    : "J S and the rim's leak") +
         (has_responding_rigid_ ? "; rigid bodies: target at t^{n+1}, their response in the marker system" : "") +
         (has_mass_spring_ ? "; mass-spring rims: target at t^{n+1}, their linearised response in the marker system)"
                           : ")");
}

void EndOfStepConstraint::write_checkpoint(const std::vector<BodyCoupling>& markers, CheckpointArrays& arrays) const {
  for (std::size_t b = 0; b < markers.size(); ++b) {
    std::vector<double> forces;
    for (const Vec2& force : markers[b].previous_force) forces.insert(forces.end(), {force[0], force[1]});
    append_body_array(arrays, "bodies_previous_force", b, forces);
    // What the body's own preconditioner block was built from, so that a restart builds the block
    // in use (it is kept while the markers drift less than ibm.preconditioner_drift cells).
    const ExactBlockInputs& inputs = arrays_.preconditioner.exact_inputs(b);
    std::vector<double> block_markers, block_arms;
    for (const Vec2& x : inputs.marker) block_markers.insert(block_markers.end(), {x[0], x[1]});
    for (const Vec2& r : inputs.arm) block_arms.insert(block_arms.end(), {r[0], r[1]});
    append_body_array(arrays, "bodies_block_markers", b, block_markers);
    append_body_array(arrays, "bodies_block_volumes", b, inputs.volume);
    append_body_array(arrays, "bodies_block_radial_factors", b, inputs.radial);
    append_body_array(arrays, "bodies_block_arms", b, block_arms);
  }
}

void EndOfStepConstraint::read_checkpoint(const CheckpointReader& read, std::vector<BodyCoupling>& markers) {
  for (std::size_t b = 0; b < markers.size(); ++b) {
    BodyCoupling& c = markers[b];
    const BodySlice values = read.body_array("bodies_previous_force", b, markers.size());
    // None before the first step, else two per marker, no more than the markers' capacity.
    if (values.size % 2 != 0 || values.size / 2 > c.previous_force.capacity())
      read.fail("bodies_previous_force", fmt::format("body {}: {} values are not two per marker for at most {} markers",
                                                     b, values.size, c.previous_force.capacity()));
    c.previous_force.resize(values.size / 2);
    for (std::size_t l = 0; l < c.previous_force.size(); ++l) c.previous_force[l] = {values.data[2 * l], values.data[2 * l + 1]};
    // The preconditioner block's inputs: none, or n markers (2 n values), n volumes, n radial
    // factors and no arms or n arms (2 n values), n no more than the markers' capacity.
    const BodySlice block_markers = read.body_array("bodies_block_markers", b, markers.size());
    const std::size_t n = block_markers.size / 2;
    if (block_markers.size % 2 != 0 || n > c.marker.capacity())
      read.fail("bodies_block_markers", fmt::format("body {}: {} values are not two per marker for at most {} markers",
                                                    b, block_markers.size, c.marker.capacity()));
    const BodySlice volumes = read.body_array("bodies_block_volumes", b, markers.size(), n);
    const BodySlice radial = read.body_array("bodies_block_radial_factors", b, markers.size(), n);
    const BodySlice arms = read.body_array("bodies_block_arms", b, markers.size());
    if (arms.size != 0 && arms.size != 2 * n)
      read.fail("bodies_block_arms", fmt::format("body {}: {} values, expected 0 or {}", b, arms.size, 2 * n));
    ExactBlockInputs& inputs = restored_inputs_;
    inputs.marker.resize(n);
    inputs.arm.resize(arms.size / 2);
    inputs.volume.assign(volumes.data, volumes.data + n);
    inputs.radial.assign(radial.data, radial.data + n);
    for (std::size_t l = 0; l < n; ++l) inputs.marker[l] = {block_markers.data[2 * l], block_markers.data[2 * l + 1]};
    for (std::size_t l = 0; l < inputs.arm.size(); ++l) inputs.arm[l] = {arms.data[2 * l], arms.data[2 * l + 1]};
    arrays_.preconditioner.restore_inputs(b, inputs);
  }
}

}  // namespace ibms
