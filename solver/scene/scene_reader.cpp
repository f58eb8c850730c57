// TOML scene -> Scene: parse, apply overrides, read each section with typed range-checked reads
// (toml_table_reader.hpp), then the checks that involve several sections (scene_checks.hpp).
#include "scene/scene_reader.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/errors.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_diagnostics.hpp"
#include "scene/scene_overrides.hpp"
#include "scene/scene_schema.hpp"
#include "scene/toml_table_reader.hpp"

namespace ibms {

namespace {

namespace schema = scene_schema;

void read_run(const TomlTableReader& table, RunSpec& run) {
  table.reject_unknown_keys(schema::run_keys);
  table.read_real("end_time", run.end_time, Need::required, positive);
  table.read_real("time_step", run.time_step, Need::optional, non_negative);
  table.read_real("cfl", run.cfl, Need::optional, {.lower = 0.0, .lower_open = true, .upper = 2.0});
  table.read_real("max_time_step", run.max_time_step, Need::optional, positive_or_infinite);
  table.read_real("steady_tolerance", run.steady_tolerance, Need::optional, non_negative);
  table.read_integer("max_steps", run.max_steps, Need::optional, /*lower=*/0);
  table.read_real("max_cfl", run.max_cfl, Need::optional, positive);
  table.read_real("max_viscous_number", run.max_viscous_number, Need::optional, non_negative);
  table.read_choice("solid_substeps", run.solid_substeps);
  table.read_choice("on_body_instability", run.on_body_instability);
  table.read_choice("on_fluid_instability", run.on_fluid_instability);
  table.read_choice("fft_plans", run.fft_plans);
}

void read_domain(const TomlTableReader& table, DomainSpec& domain) {
  table.reject_unknown_keys(schema::domain_keys);
  table.read_real("length_x", domain.length_x, Need::required, positive);
  table.read_real("length_y", domain.length_y, Need::required, positive);
  // Four cells is the smallest grid the stencils (and a 4-point kernel) fit in.
  table.read_integer("cells_x", domain.cells_x, Need::required, /*lower=*/4);
  table.read_integer("cells_y", domain.cells_y, Need::required, /*lower=*/4);
  table.read_bool("periodic_x", domain.periodic_x);
  table.read_bool("periodic_y", domain.periodic_y);
}

void read_fluid(const TomlTableReader& table, FluidSpec& fluid) {
  table.reject_unknown_keys(schema::fluid_keys);
  table.read_real("density", fluid.density, Need::optional, positive);
  table.read_real("kinematic_viscosity", fluid.kinematic_viscosity, Need::required, positive);
  table.read_pair("gravity", fluid.gravity, Need::optional);
  table.read_choice("convection", fluid.convection);
  table.read_choice("wall_closure", fluid.wall_closure);
  table.read_real("interpolation_time", fluid.interpolation_time, Need::optional, non_negative);
}

// The four sides of the box (fluid/boundary_conditions.hpp). A side of a periodic direction is
// "periodic" by default; "periodic" on both sides of a direction makes it periodic; any other mix
// of periodic and non-periodic on one direction is refused, as is an outflow pair without an
// inflow (nothing drives a flow through them) and an inflow without an outflow (the fluid cannot
// leave: the pressure problem has no solution).
void read_walls(const TomlTableReader& table, DomainSpec& domain, WallsSpec& walls) {
  table.reject_unknown_keys(schema::wall_names);
  WallSpec* const sides[] = {&walls.left, &walls.right, &walls.bottom, &walls.top};
  TomlTableReader readers[] = {table.sub_table("left"), table.sub_table("right"), table.sub_table("bottom"),
                               table.sub_table("top")};
  for (std::size_t s = 0; s < 4; ++s) {
    const TomlTableReader& side = readers[s];
    WallSpec& w = *sides[s];
    side.reject_unknown_keys(schema::wall_keys);
    const bool periodic_axis = s < 2 ? domain.periodic_x : domain.periodic_y;
    if (periodic_axis) w.kind = WallSpec::Kind::periodic;
    const bool kind_given = side.read_choice("kind", w.kind);
    if (periodic_axis && w.kind != WallSpec::Kind::periodic)
      side.fail("kind", fmt::format("is '{}', but domain.periodic_{} = true makes this side periodic",
                                    schema::name_of(w.kind),
                                    s < 2 ? "x" : "y"));
    (void)kind_given;
    side.reject_keys_outside(schema::keys_of_side_kind(w.kind),
                             fmt::format("a side of kind '{}'", schema::name_of(w.kind)));
    if (w.kind == WallSpec::Kind::wall) {
      side.read_real("speed", w.speed, Need::optional, any_finite);
      side.read_real("stop_time", w.stop_time, Need::optional, non_negative_or_infinite);
    } else if (w.kind == WallSpec::Kind::inflow) {
      side.read_choice("profile", w.profile);
      side.read_real("velocity", w.velocity, Need::required, positive);
      side.read_choice("time_factor", w.time_factor);
      side.read_real("ramp_time", w.ramp_time, Need::optional, positive);
      side.read_real("factor_offset", w.factor_offset, Need::optional, any_finite);
      side.read_real("factor_amplitude", w.factor_amplitude, Need::optional, any_finite);
      side.read_real("factor_period", w.factor_period, Need::optional, positive);
      if (w.time_factor == WallSpec::TimeFactor::ramp && !(w.ramp_time > 0.0))
        side.fail("ramp_time", "must be given (> 0) with time_factor = 'ramp'");
      if (w.time_factor == WallSpec::TimeFactor::sinusoidal && !(w.factor_period > 0.0))
        side.fail("factor_period", "must be given (> 0) with time_factor = 'sinusoidal'");
    }
  }
  // Periodic directions: both sides or neither.
  for (int axis = 0; axis < 2; ++axis) {
    const WallSpec &low = *sides[2 * axis], &high = *sides[2 * axis + 1];
    const bool low_periodic = low.kind == WallSpec::Kind::periodic;
    const bool high_periodic = high.kind == WallSpec::Kind::periodic;
    if (low_periodic != high_periodic) {
      const int lone = low_periodic ? 2 * axis : 2 * axis + 1;
      readers[lone].fail("kind", fmt::format("'periodic' needs the opposite side periodic too, but walls.{}.kind = '{}'",
                                             schema::wall_names[low_periodic ? 2 * axis + 1 : 2 * axis],
                                             schema::name_of(low_periodic ? high.kind : low.kind)));
    }
    if (low_periodic) (axis == 0 ? domain.periodic_x : domain.periodic_y) = true;
  }
  int inflows = 0, outflows = 0;
  for (const WallSpec* w : sides) {
    inflows += w->kind == WallSpec::Kind::inflow;
    outflows += w->kind == WallSpec::Kind::outflow;
  }
  for (std::size_t s = 0; s < 4; ++s) {
    if (sides[s]->kind == WallSpec::Kind::inflow && outflows == 0)
      readers[s].fail("kind", "an inflow needs an outflow side: with walls or periodic sides elsewhere the fluid "
                              "it brings in cannot leave (the pressure equation has no solution)");
    if (sides[s]->kind == WallSpec::Kind::outflow && inflows == 0 && outflows > 1)
      readers[s].fail("kind", "several outflow sides without an inflow: nothing drives a flow through them, and "
                              "the flux between them is undetermined");
  }
}

void read_ibm(const TomlTableReader& table, IbmSpec& ibm) {
  table.reject_unknown_keys(schema::ibm_keys);
  table.read_choice("kernel", ibm.kernel);
  table.read_integer("forcing_passes", ibm.forcing_passes, Need::optional, /*lower=*/1);
  table.read_choice("forcing_stage", ibm.forcing_stage);
  table.read_choice("inner_fluid_inertia", ibm.inner_fluid_inertia);
  table.read_bool("sub_markers", ibm.sub_markers);
  table.read_real("marker_retraction", ibm.marker_retraction, Need::optional, Bounds{0.0, false, 1.0, true});
  table.read_choice("coupling", ibm.coupling);
  table.read_real("slip_tolerance", ibm.slip_tolerance, Need::optional, Bounds{0.0, true, 1.0, false});
  table.read_integer("max_coupling_iterations", ibm.max_coupling_iterations, Need::optional, /*lower=*/1);
  table.read_real_or_auto("preconditioner_drift", ibm.preconditioner_drift, Bounds{0.0, false, 1.0, false},
                          IbmSpec::preconditioner_drift_auto);
  table.read_choice("constrained_velocity", ibm.constrained_velocity);
  table.read_real("virtual_mass_coefficient", ibm.virtual_mass_coefficient, Need::optional, Bounds{0.0, false, 10.0, false});
  table.read_choice("rigid_response", ibm.rigid_response);
  table.read_choice("rim_preconditioner", ibm.rim_preconditioner);
}

void read_swelling(const TomlTableReader& table, double diameter, SwellingSpec& swelling) {
  if (!table.present()) return;  // no swelling table: the body keeps its diameter
  table.reject_unknown_keys(schema::swelling_keys);
  swelling.enabled = true;
  table.read_real("onset_time", swelling.onset_time, Need::optional, non_negative);
  table.read_real("rate", swelling.rate, Need::required, positive);
  table.read_real("max_diameter", swelling.max_diameter, Need::required, positive);
  if (swelling.max_diameter < diameter) {  // swelling never shrinks a body
    table.fail("max_diameter", fmt::format("must be >= the body diameter {}, got {}", diameter,
                                           swelling.max_diameter));
  }
}

void read_body(const TomlTableReader& table, BodySpec& body) {
  table.reject_unknown_keys(schema::body_keys);
  table.read_choice("kind", body.kind);
  table.reject_keys_outside(schema::keys_of_body_kind(body.kind),
                            fmt::format("a body of kind '{}'", schema::name_of(body.kind)));
  table.read_pair("centre", body.centre, Need::required);
  table.read_pair("velocity", body.velocity, Need::optional);
  table.read_real("angular_velocity", body.angular_velocity, Need::optional, any_finite);
  table.read_real("diameter", body.diameter, Need::required, positive);
  table.read_integer("n_surface_points", body.n_surface_points, Need::required, /*lower=*/3);
  table.read_real("reference_speed", body.reference_speed, Need::optional, non_negative);
  table.read_real("reference_length", body.reference_length, Need::optional, non_negative);
  if (body.kind == BodySpec::Kind::prescribed) {
    table.read_pair("oscillation_amplitude", body.oscillation_amplitude, Need::optional);
    table.read_real("angle_amplitude", body.angle_amplitude, Need::optional, any_finite);
    table.read_real("oscillation_period", body.oscillation_period, Need::optional, non_negative);
    table.read_real("oscillation_phase", body.oscillation_phase, Need::optional, any_finite);
    const bool oscillates = body.oscillation_amplitude[0] != 0.0 || body.oscillation_amplitude[1] != 0.0 ||
                            body.angle_amplitude != 0.0;
    if (oscillates && !(body.oscillation_period > 0.0))
      table.fail("oscillation_period", "must be > 0 when an oscillation amplitude is given");
    return;
  }
  table.read_real("density", body.density, Need::required, positive);
  if (body.kind == BodySpec::Kind::rigid) return;
  table.read_real("spring_stiffness", body.spring_stiffness, Need::required, positive);
  table.read_real("spring_damping", body.spring_damping, Need::optional, non_negative);
  table.read_real("restitution_coefficient", body.restitution_coefficient, Need::optional,
                  unit_interval_open_closed);
  table.read_bool("cross_springs", body.cross_springs);
  table.read_choice("mass_lumping", body.mass_lumping);
  table.read_choice("spring_integrator", body.spring_integrator);
  read_swelling(table.sub_table("swelling"), body.diameter, body.swelling);
}

void read_bodies(const toml::node* node, SceneDiagnostics& diagnostics, std::vector<BodySpec>& bodies) {
  if (node == nullptr) return;
  const toml::array* array = node->as_array();
  if (array == nullptr) {
    diagnostics.fail_at(node->source(), "bodies",
                        fmt::format("expected an array of tables [[bodies]], got {}",
                                    toml_type_name(node->type())));
  }
  for (std::size_t b = 0; b < array->size(); ++b) {
    const toml::node& element = *array->get(b);
    const std::string path = fmt::format("bodies.{}", b);
    const toml::table* table = element.as_table();
    if (table == nullptr) {
      diagnostics.fail_at(element.source(), path,
                          fmt::format("expected a table, got {}", toml_type_name(element.type())));
    }
    diagnostics.remember(path, element.source());
    read_body(TomlTableReader(table, path, diagnostics), bodies.emplace_back());
  }
}

// Top-level keys must be known sections, each a table ([[bodies]] an array of tables).
void reject_unknown_sections(const toml::table& root, const SceneDiagnostics& diagnostics) {
  for (auto&& [key, node] : root) {
    const std::string_view name = key.str();
    bool known = false;
    for (const std::string_view section : schema::section_names) known = known || section == name;
    if (name == "body_groups") {
      diagnostics.fail_at(key.source(), "body_groups",
                          "[[body_groups]] is not supported yet; list each body under [[bodies]]");
    }
    if (!known) {
      // A key written above its section header lands at the top level: point to its section.
      for (const std::string_view section : schema::section_names) {
        for (const std::string_view section_key : schema::keys_of_section(section)) {
          if (section_key == name) {
            diagnostics.fail_at(key.source(), std::string(name),
                                fmt::format("unknown top-level key, did you mean {}.{} (put it under [{}])?",
                                            section, name, section));
          }
        }
      }
      diagnostics.fail_at(key.source(), std::string(name),
                          fmt::format("unknown section{} (allowed: {})",
                                      schema::suggestion_suffix(name, schema::section_names),
                                      schema::join_names(schema::section_names)));
    }
    if (name != "bodies" && !node.is_table()) {
      diagnostics.fail_at(node.source(), std::string(name),
                          fmt::format("expected a table [{}], got {}", name, toml_type_name(node.type())));
    }
  }
}

Scene scene_from_table(const toml::table& root, SceneDiagnostics& diagnostics) {
  reject_unknown_sections(root, diagnostics);
  const auto section = [&](std::string_view name) {
    const toml::node* node = root.get(name);
    return TomlTableReader(node == nullptr ? nullptr : node->as_table(), std::string(name), diagnostics);
  };
  Scene scene;
  read_run(section("run"), scene.run);
  read_domain(section("domain"), scene.domain);
  read_fluid(section("fluid"), scene.fluid);
  read_walls(section("walls"), scene.domain, scene.walls);
  read_ibm(section("ibm"), scene.ibm);
  read_bodies(root.get("bodies"), diagnostics, scene.bodies);
  TomlTableReader contact = section("contact");
  contact.reject_unknown_keys(schema::contact_keys);
  contact.read_real("stiffness", scene.contact.stiffness, Need::optional, non_negative);
  contact.read_real("restitution_coefficient", scene.contact.restitution_coefficient, Need::optional,
                    unit_interval_open_closed);
  contact.read_real("cds_radius", scene.contact.cds_radius, Need::optional, non_negative);
  contact.read_real("cds_radius_fraction", scene.contact.cds_radius_fraction, Need::optional,
                    non_negative);
  contact.read_bool("walls", scene.contact.walls);
  contact.read_bool("centre_point", scene.contact.centre_point);
  contact.read_choice("time_stepping", scene.contact.time_stepping);
  contact.read_choice("inner_step", scene.contact.inner_step);
  contact.read_real("outer_step_fraction", scene.contact.outer_step_fraction, Need::optional,
                    unit_interval_open_closed);
  contact.read_choice("model", scene.contact.model);
  // Finite and > 0 here; the lower bound of one fluid step, with its reason, in scene_checks.cpp.
  contact.read_real("collision_steps", scene.contact.collision_steps, Need::optional, positive);
  TomlTableReader output = section("output");
  output.reject_unknown_keys(schema::output_keys);
  output.read_string("file", scene.output.file);
  output.read_integer("series_every", scene.output.series_every, Need::optional, /*lower=*/1);
  output.read_real("snapshot_interval", scene.output.snapshot_interval, Need::optional, non_negative);
  output.read_bool("centreline_profiles", scene.output.centreline_profiles);
  output.read_bool("progress", scene.output.progress);
  output.read_integer("checkpoint_every", scene.output.checkpoint_every, Need::optional, /*lower=*/0);
  output.read_pairs("probes", scene.output.probes);
  for (std::size_t k = 0; k < scene.output.probes.size(); ++k) {
    const auto& p = scene.output.probes[k];
    if (p[0] < 0.0 || p[0] > scene.domain.length_x || p[1] < 0.0 || p[1] > scene.domain.length_y)
      output.fail("probes", fmt::format("point {} = [{}, {}] lies outside the box [0, {}] x [0, {}]", k, p[0], p[1],
                                        scene.domain.length_x, scene.domain.length_y));
  }
  return scene;
}

}  // namespace

Scene read_scene_string(const std::string& toml_text, const std::string& source_name,
                        const std::vector<std::string>& overrides) {
  SceneDiagnostics diagnostics(source_name);
  try {
    toml::table root;
    try {
      root = toml::parse(std::string_view(toml_text), std::string_view(source_name));
    } catch (const toml::parse_error& error) {
      diagnostics.fail_at(error.source(), "TOML syntax", std::string(error.description()));
    }
    apply_scene_overrides(root, overrides, diagnostics);
    Scene scene = scene_from_table(root, diagnostics);
    check_scene_consistency(scene, diagnostics);
    scene.source_file = source_name;
    scene.resolved_text = resolved_scene_toml(scene);
    return scene;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    // Fuzzed input must never crash the program: anything unexpected is still bad input.
    diagnostics.fail_plain("scene", fmt::format("cannot be read: {}", error.what()));
  }
}

Scene read_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(fmt::format("{}: cannot read scene file: is a directory", one_line(path)));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw InputError(fmt::format("{}: cannot open scene file: {}", one_line(path), std::strerror(errno)));
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw InputError(fmt::format("{}: cannot read scene file", one_line(path)));
  return read_scene_string(text.str(), path, overrides);
}

}  // namespace ibms
