// The fully resolved scene as TOML (scene_reader.hpp: resolved_scene_toml): every key with its
// value, defaults included, sections in the documented order. Every run stores this text in its
// output (docs/design.md §5), so reading it back must give the same Scene: floats are written with
// the shortest text that round-trips, strings are TOML-escaped.
#include <fmt/format.h>

#include <cmath>

#include "scene/scene_diagnostics.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"

namespace ibms {

namespace {

// Shortest round-trip text, always a TOML float (never read back as an integer).
std::string toml_float(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

std::string toml_pair(const std::array<double, 2>& pair) {
  return fmt::format("[{}, {}]", toml_float(pair[0]), toml_float(pair[1]));
}

std::string toml_bool(bool value) { return value ? "true" : "false"; }

// TOML basic string with escapes.
std::string toml_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"') out += "\\\"";
    else if (c == '\\') out += "\\\\";
    else if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (byte < 0x20 || byte == 0x7f) out += fmt::format("\\u{:04X}", byte);
    else out += c;
  }
  return out + "\"";
}

void append_body(std::string& out, const BodySpec& body) {
  out += "\n[[bodies]]\n";
  out += fmt::format("kind = {}\n", toml_string(scene_schema::name_of(body.kind)));
  out += fmt::format("centre = {}\n", toml_pair(body.centre));
  out += fmt::format("velocity = {}\n", toml_pair(body.velocity));
  out += fmt::format("angular_velocity = {}\n", toml_float(body.angular_velocity));
  out += fmt::format("diameter = {}\n", toml_float(body.diameter));
  out += fmt::format("n_surface_points = {}\n", body.n_surface_points);
  out += fmt::format("reference_speed = {}\n", toml_float(body.reference_speed));
  out += fmt::format("reference_length = {}\n", toml_float(body.reference_length));
  if (body.kind == BodySpec::Kind::prescribed) {
    out += fmt::format("oscillation_amplitude = {}\n", toml_pair(body.oscillation_amplitude));
    out += fmt::format("angle_amplitude = {}\n", toml_float(body.angle_amplitude));
    out += fmt::format("oscillation_period = {}\n", toml_float(body.oscillation_period));
    out += fmt::format("oscillation_phase = {}\n", toml_float(body.oscillation_phase));
    return;
  }
  out += fmt::format("density = {}\n", toml_float(body.density));
  if (body.kind == BodySpec::Kind::rigid) return;
  out += fmt::format("spring_stiffness = {}\n", toml_float(body.spring_stiffness));
  if (body.spring_damping >= 0.0) out += fmt::format("spring_damping = {}\n", toml_float(body.spring_damping));
  else out += "# spring_damping not set: derived from restitution_coefficient\n";
  out += fmt::format("restitution_coefficient = {}\n", toml_float(body.restitution_coefficient));
  out += fmt::format("cross_springs = {}\n", toml_bool(body.cross_springs));
  out += fmt::format("mass_lumping = {}\n", toml_string(scene_schema::name_of(body.mass_lumping)));
  out += fmt::format("spring_integrator = {}\n", toml_string(scene_schema::name_of(body.spring_integrator)));
  if (body.swelling.enabled) {
    out += fmt::format("swelling = {{ onset_time = {}, rate = {}, max_diameter = {} }}\n",
                       toml_float(body.swelling.onset_time), toml_float(body.swelling.rate),
                       toml_float(body.swelling.max_diameter));
  } else {
    out += "# no swelling\n";
  }
}

}  // namespace

std::string resolved_scene_toml(const Scene& scene) {
  std::string out = "# Resolved scene (every key, defaults filled in)";
  if (!scene.source_file.empty()) out += " from " + one_line(scene.source_file);
  out += "\n\n[run]\n";
  const RunSpec& run = scene.run;
  out += fmt::format("end_time = {}\n", toml_float(run.end_time));
  out += fmt::format("time_step = {}\n", toml_float(run.time_step));
  out += fmt::format("cfl = {}\n", toml_float(run.cfl));
  out += fmt::format("max_time_step = {}\n", toml_float(run.max_time_step));
  out += fmt::format("steady_tolerance = {}\n", toml_float(run.steady_tolerance));
  out += fmt::format("max_steps = {}\n", run.max_steps);
  out += fmt::format("max_cfl = {}\n", toml_float(run.max_cfl));
  out += fmt::format("max_viscous_number = {}\n", toml_float(run.max_viscous_number));
  out += fmt::format("solid_substeps = {}\n", toml_string(scene_schema::name_of(run.solid_substeps)));
  out += fmt::format("on_body_instability = {}\n", toml_string(scene_schema::name_of(run.on_body_instability)));
  out += fmt::format("on_fluid_instability = {}\n", toml_string(scene_schema::name_of(run.on_fluid_instability)));
  out += fmt::format("fft_plans = {}\n", toml_string(scene_schema::name_of(run.fft_plans)));

  const DomainSpec& domain = scene.domain;
  out += "\n[domain]\n";
  out += fmt::format("length_x = {}\n", toml_float(domain.length_x));
  out += fmt::format("length_y = {}\n", toml_float(domain.length_y));
  out += fmt::format("cells_x = {}\n", domain.cells_x);
  out += fmt::format("cells_y = {}\n", domain.cells_y);
  out += fmt::format("periodic_x = {}\n", toml_bool(domain.periodic_x));
  out += fmt::format("periodic_y = {}\n", toml_bool(domain.periodic_y));

  out += "\n[fluid]\n";
  out += fmt::format("density = {}\n", toml_float(scene.fluid.density));
  out += fmt::format("kinematic_viscosity = {}\n", toml_float(scene.fluid.kinematic_viscosity));
  out += fmt::format("convection = {}\n", toml_string(scene_schema::name_of(scene.fluid.convection)));
  out += fmt::format("wall_closure = {}\n", toml_string(scene_schema::name_of(scene.fluid.wall_closure)));
  out += fmt::format("gravity = {}\n", toml_pair(scene.fluid.gravity));
  // Only when set: the scenes that do not use it keep the resolved text (and restarts) they had.
  if (scene.fluid.interpolation_time > 0.0)
    out += fmt::format("interpolation_time = {}\n", toml_float(scene.fluid.interpolation_time));

  out += "\n[walls]\n";
  const std::pair<const char*, const WallSpec*> walls[] = {
      {"left", &scene.walls.left}, {"right", &scene.walls.right},
      {"bottom", &scene.walls.bottom}, {"top", &scene.walls.top}};
  for (const auto& [name, wall] : walls) {
    out += fmt::format("[walls.{}]\nkind = {}\n", name, toml_string(scene_schema::name_of(wall->kind)));
    if (wall->kind == WallSpec::Kind::wall)
      out += fmt::format("speed = {}\nstop_time = {}\n", toml_float(wall->speed), toml_float(wall->stop_time));
    if (wall->kind == WallSpec::Kind::inflow)
      out += fmt::format("profile = {}\nvelocity = {}\ntime_factor = {}\n",
                         toml_string(scene_schema::name_of(wall->profile)),
                         toml_float(wall->velocity), toml_string(scene_schema::name_of(wall->time_factor)));
    if (wall->kind == WallSpec::Kind::inflow && wall->time_factor == WallSpec::TimeFactor::ramp)
      out += fmt::format("ramp_time = {}\n", toml_float(wall->ramp_time));
    if (wall->kind == WallSpec::Kind::inflow && wall->time_factor == WallSpec::TimeFactor::sinusoidal)
      out += fmt::format("factor_offset = {}\nfactor_amplitude = {}\nfactor_period = {}\n",
                         toml_float(wall->factor_offset), toml_float(wall->factor_amplitude),
                         toml_float(wall->factor_period));
  }

  const IbmSpec& ibm = scene.ibm;
  out += "\n[ibm]\n";
  out += fmt::format("kernel = {}\n", toml_string(scene_schema::name_of(ibm.kernel)));
  out += fmt::format("forcing_passes = {}\n", ibm.forcing_passes);
  out += fmt::format("forcing_stage = {}\n", toml_string(scene_schema::name_of(ibm.forcing_stage)));
  out += fmt::format("inner_fluid_inertia = {}\n", toml_string(scene_schema::name_of(ibm.inner_fluid_inertia)));
  out += fmt::format("sub_markers = {}\n", toml_bool(ibm.sub_markers));
  out += fmt::format("marker_retraction = {}\n", toml_float(ibm.marker_retraction));
  out += fmt::format("coupling = {}\n", toml_string(scene_schema::name_of(ibm.coupling)));
  out += fmt::format("slip_tolerance = {}\n", toml_float(ibm.slip_tolerance));
  out += fmt::format("max_coupling_iterations = {}\n", ibm.max_coupling_iterations);
  out += ibm.preconditioner_drift == IbmSpec::preconditioner_drift_auto
             ? std::string("preconditioner_drift = \"auto\"\n")
             : fmt::format("preconditioner_drift = {}\n", toml_float(ibm.preconditioner_drift));
  out += fmt::format("constrained_velocity = {}\n", toml_string(scene_schema::name_of(ibm.constrained_velocity)));
  out += fmt::format("virtual_mass_coefficient = {}\n", toml_float(ibm.virtual_mass_coefficient));
  out += fmt::format("rigid_response = {}\n", toml_string(scene_schema::name_of(ibm.rigid_response)));
  out += fmt::format("rim_preconditioner = {}\n", toml_string(scene_schema::name_of(ibm.rim_preconditioner)));

  for (const BodySpec& body : scene.bodies) append_body(out, body);

  const ContactSpec& contact = scene.contact;
  out += "\n[contact]\n";
  out += fmt::format("stiffness = {}\n", toml_float(contact.stiffness));
  out += fmt::format("restitution_coefficient = {}\n", toml_float(contact.restitution_coefficient));
  out += fmt::format("cds_radius = {}\n", toml_float(contact.cds_radius));
  out += fmt::format("cds_radius_fraction = {}\n", toml_float(contact.cds_radius_fraction));
  out += fmt::format("walls = {}\n", toml_bool(contact.walls));
  out += fmt::format("centre_point = {}\n", toml_bool(contact.centre_point));
  out += fmt::format("time_stepping = {}\n", toml_string(scene_schema::name_of(contact.time_stepping)));
  out += fmt::format("inner_step = {}\n", toml_string(scene_schema::name_of(contact.inner_step)));
  out += fmt::format("outer_step_fraction = {}\n", toml_float(contact.outer_step_fraction));
  out += fmt::format("model = {}\n", toml_string(scene_schema::name_of(contact.model)));
  out += fmt::format("collision_steps = {}\n", toml_float(contact.collision_steps));

  const OutputSpec& output = scene.output;
  out += "\n[output]\n";
  out += fmt::format("file = {}\n", toml_string(output.file));
  out += fmt::format("series_every = {}\n", output.series_every);
  out += fmt::format("snapshot_interval = {}\n", toml_float(output.snapshot_interval));
  out += fmt::format("centreline_profiles = {}\n", toml_bool(output.centreline_profiles));
  out += fmt::format("progress = {}\n", toml_bool(output.progress));
  out += fmt::format("checkpoint_every = {}\n", output.checkpoint_every);
  if (!output.probes.empty()) {
    out += "probes = [";
    for (std::size_t k = 0; k < output.probes.size(); ++k)
      out += fmt::format("{}{}", k ? ", " : "", toml_pair(output.probes[k]));
    out += "]\n";
  }
  return out;
}

}  // namespace ibms
