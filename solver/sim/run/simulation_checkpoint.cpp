// Writing and restoring the restart state of a Simulation (simulation_checkpoint.hpp).
#include "sim/run/simulation_checkpoint.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "fluid/spectral_solver.hpp"
#include "sim/checks/fluid_guard.hpp"

namespace ibms {
namespace {

using Arrays = CheckpointArrays;
using Scalars = std::map<std::string, double>;

std::vector<double> cell_values(const CellField& field) {  // ghost layers included
  const double* data = field.data();
  return std::vector<double>(data, data + static_cast<std::size_t>(field.stride()) * (field.ny() + 2));
}

std::vector<double> interleaved(const std::vector<Vec2>& points) {
  std::vector<double> values;
  values.reserve(2 * points.size());
  for (const Vec2& p : points) values.insert(values.end(), {p[0], p[1]});
  return values;
}

// First line where two texts differ, for the message.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  while (true) {
    const bool more_a = static_cast<bool>(std::getline(sa, la));
    const bool more_b = static_cast<bool>(std::getline(sb, lb));
    if (!more_a && !more_b) return "";
    if (!more_a) la = "(end)";
    if (!more_b) lb = "(end)";
    if (la != lb) return fmt::format("checkpoint has '{}', this scene '{}'", la, lb);
  }
}

}  // namespace

std::string restart_relevant_scene(const std::string& resolved_scene) {
  std::istringstream in(resolved_scene);
  std::string line, kept;
  bool skipping = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') skipping = line == "[run]" || line == "[output]";
    if (!skipping) kept += line + "\n";
  }
  return kept;
}

void write_simulation_checkpoint(OutputFile& out, const Simulation& sim, double next_snapshot_time) {
  const FluidState& f = sim.fluid();
  Arrays arrays{
      {"fluid_velocity_x", cell_values(f.velocity_x)},
      {"fluid_velocity_y", cell_values(f.velocity_y)},
      {"fluid_pressure", cell_values(f.pressure)},
      {"fluid_convection_x_prev", cell_values(f.convection_x_prev)},
      {"fluid_convection_y_prev", cell_values(f.convection_y_prev)},
      {"fluid_velocity_face_x", f.velocity_face_x.values()},
      {"fluid_velocity_face_y", f.velocity_face_y.values()},
  };
  Scalars scalars{
      {"time", f.time},
      {"step", static_cast<double>(f.step)},
      {"time_step_prev", f.time_step_prev},
      {"has_convection_prev", f.has_convection_prev ? 1.0 : 0.0},
      {"next_snapshot_time", next_snapshot_time},
      {"total_contact_work", sim.stats().total_contact_work},
      {"fluid_guard_speed_scale", sim.instability().fluid_guard.speed_scale},
      {"fluid_guard_initial_energy", sim.instability().fluid_guard.initial_energy},
      {"fluid_guard_input_work", sim.instability().fluid_guard.input_work},
      {"fluid_guard_boundary_power", sim.instability().fluid_guard.boundary_power},
      {"nx", static_cast<double>(sim.grid().nx)},
      {"ny", static_cast<double>(sim.grid().ny)},
      {"n_bodies", static_cast<double>(sim.bodies().size())},
  };
  // Per-body arrays, all bodies in one dataset each (append_body_array).
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const MassSpringBody& body = sim.bodies()[b];
    const BodyCoupling& c = sim.markers()[b];
    append_body_array(arrays, "bodies_position", b, interleaved(body.position));
    append_body_array(arrays, "bodies_velocity", b, interleaved(body.velocity));
    append_body_array(arrays, "bodies_mass", b, body.mass);
    append_body_array(arrays, "bodies_diameter", b, {body.diameter});
    append_body_array(arrays, "bodies_triangle_momentum", b, interleaved(c.triangle_momentum));
    append_body_array(arrays, "bodies_inner_angular_momentum", b,
                      {c.inner_angular_momentum, c.inner_reference_centre[0], c.inner_reference_centre[1]});
    std::vector<double> rigid, acceleration;
    if (body.kind != BodyKind::mass_spring) {
      const RigidState& r = sim.rigid()[b].state;
      rigid = {r.centre[0], r.centre[1], r.angle, r.velocity[0], r.velocity[1], r.angular_velocity};
      // The virtual mass's right-hand side: the previous fluid step's acceleration.
      if (sim.rigid()[b].virtual_mass > 0.0) {
        const auto& a = sim.rigid()[b].previous_acceleration;
        acceleration = {a[0], a[1], a[2]};
      }
    }
    append_body_array(arrays, "bodies_rigid_state", b, rigid);
    append_body_array(arrays, "bodies_rigid_acceleration", b, acceleration);
  }
  sim.coupling().write_checkpoint(sim.markers(), arrays);  // the coupling's own section
  // The FFTW planner state, one character code per value (optional on reading).
  const std::string wisdom = fft_planner_wisdom();
  arrays["fftw_wisdom"] = std::vector<double>(wisdom.begin(), wisdom.end());
  out.write_checkpoint(arrays, scalars, checkpoint_format_version);
}

void import_checkpoint_planner_wisdom(const Checkpoint& checkpoint) {
  const auto found = checkpoint.arrays.find("fftw_wisdom");
  if (found == checkpoint.arrays.end()) return;
  std::string wisdom;
  wisdom.reserve(found->second.size());
  for (double c : found->second) {
    if (!(c >= 1.0 && c <= 127.0)) return;  // not text: ignore, plans are measured afresh
    wisdom.push_back(static_cast<char>(c));
  }
  import_fft_planner_wisdom(wisdom);
}

double restore_simulation(const Checkpoint& checkpoint, const std::string& path, Simulation& sim) {
  if (checkpoint.format_version != checkpoint_format_version) {
    throw InputError(fmt::format("{}: /checkpoint format_version {}: this ibms reads format_version {} only",
                                 path, checkpoint.format_version, checkpoint_format_version));
  }
  const std::string difference = first_difference(restart_relevant_scene(checkpoint.scene),
                                                  restart_relevant_scene(sim.scene().resolved_text));
  if (!difference.empty()) {
    throw InputError(fmt::format("{}: scene: the checkpoint was written for a different scene (only [run] and "
                                 "[output] may change on restart): {}", path, difference));
  }
  const CheckpointReader read(checkpoint, path);
  if (read.count("nx") != sim.grid().nx || read.count("ny") != sim.grid().ny) read.fail("nx", "grid size differs");
  if (read.count("n_bodies") != static_cast<long>(sim.bodies().size())) read.fail("n_bodies", "body count differs");
  const double next_snapshot_time = read.scalar("next_snapshot_time");  // +inf without snapshots
  if (std::isnan(next_snapshot_time)) read.fail("next_snapshot_time", "is NaN");
  FluidState& f = sim.fluid();
  f.time = read.non_negative("time");
  f.step = read.count("step");
  f.time_step_prev = read.non_negative("time_step_prev");
  f.has_convection_prev = read.scalar("has_convection_prev") != 0.0;
  // The instability guard's contact-work sum (absent from checkpoints of ibms <= 0.2: starts at 0).
  if (checkpoint.scalars.count("total_contact_work") != 0) sim.stats().total_contact_work = read.scalar("total_contact_work");
  read.into("fluid_velocity_x", f.velocity_x);
  read.into("fluid_velocity_y", f.velocity_y);
  read.into("fluid_pressure", f.pressure);
  read.into("fluid_convection_x_prev", f.convection_x_prev);
  read.into("fluid_convection_y_prev", f.convection_y_prev);
  read.into("fluid_velocity_face_x", f.velocity_face_x);
  read.into("fluid_velocity_face_y", f.velocity_face_y);
  // The fluid guard's budget goes on as it was; a checkpoint without it (older ibms) starts it from
  // the restored field.
  start_fluid_guard(sim);
  if (checkpoint.scalars.count("fluid_guard_input_work") != 0) {
    FluidGuard& guard = sim.instability().fluid_guard;
    guard.speed_scale = read.non_negative("fluid_guard_speed_scale");
    guard.initial_energy = read.non_negative("fluid_guard_initial_energy");
    guard.input_work = read.non_negative("fluid_guard_input_work");
    guard.boundary_power = read.scalar("fluid_guard_boundary_power");
    guard.energy_floor = FluidGuard::floor_fraction * 0.5 * guard.speed_scale * guard.speed_scale *
                         sim.grid().length_x * sim.grid().length_y;
  }
  const std::size_t n_bodies = sim.bodies().size();
  const auto points = [&](const std::string& name, std::size_t b, std::vector<Vec2>& out) {
    const BodySlice v = read.body_array(name, b, n_bodies, 2 * out.size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {v.data[2 * k], v.data[2 * k + 1]};
  };
  for (std::size_t b = 0; b < n_bodies; ++b) {
    MassSpringBody& body = sim.bodies()[b];
    BodyCoupling& c = sim.markers()[b];
    points("bodies_position", b, body.position);
    points("bodies_velocity", b, body.velocity);
    const BodySlice mass = read.body_array("bodies_mass", b, n_bodies, body.mass.size());
    body.mass.assign(mass.data, mass.data + mass.size);
    body.diameter = read.body_array("bodies_diameter", b, n_bodies, 1).data[0];
    points("bodies_triangle_momentum", b, c.triangle_momentum);
    const BodySlice angular = read.body_array("bodies_inner_angular_momentum", b, n_bodies, 3);
    c.inner_angular_momentum = angular.data[0];
    c.inner_reference_centre = {angular.data[1], angular.data[2]};
    const bool rigid = body.kind != BodyKind::mass_spring;
    const BodySlice r = read.body_array("bodies_rigid_state", b, n_bodies, rigid ? 6 : 0);
    const bool virtual_mass = rigid && sim.rigid()[b].virtual_mass > 0.0;
    const BodySlice a = read.body_array("bodies_rigid_acceleration", b, n_bodies, virtual_mass ? 3 : 0);
    if (rigid) sim.rigid()[b].state = {{r.data[0], r.data[1]}, r.data[2], {r.data[3], r.data[4]}, r.data[5]};
    if (virtual_mass) sim.rigid()[b].previous_acceleration = {a.data[0], a.data[1], a.data[2]};
  }
  sim.coupling().read_checkpoint(read, sim.markers());
  return next_snapshot_time;
}

}  // namespace ibms
