// The scene schema: which sections and keys a scene may contain (docs/design.md §4). One list serves
// the reader (unknown-key errors), the `--set` overrides (key validation) and the suggestions
// for misspelt keys, so the three can never disagree. Key names equal the fields in scene.hpp.
// The values of each option with a fixed set of names are an enum (scene.hpp) with one table of
// (value, name) pairs here, Choices<Enum>: the reader parses with it (scene names in messages,
// in the table's order), the resolved scene and messages write name_of(value).
#pragma once
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace ibms::scene_schema {

// Top-level sections in the order a scene lists them.
inline constexpr std::string_view section_names[] = {"run",    "domain", "fluid",   "walls",
                                                     "ibm",    "bodies", "contact", "output"};
inline constexpr std::string_view run_keys[] = {"end_time",         "time_step", "cfl",
                                                "max_time_step",    "steady_tolerance",
                                                "max_steps",        "max_cfl",
                                                "max_viscous_number", "solid_substeps", "on_body_instability",
                                                "on_fluid_instability", "fft_plans"};
inline constexpr std::string_view domain_keys[] = {"length_x", "length_y",   "cells_x",
                                                   "cells_y",  "periodic_x", "periodic_y"};
inline constexpr std::string_view fluid_keys[] = {"density", "kinematic_viscosity", "gravity", "convection",
                                                  "wall_closure", "interpolation_time"};
inline constexpr std::string_view wall_names[] = {"left", "right", "bottom", "top"};
inline constexpr std::string_view wall_keys[] = {"kind",     "speed",       "stop_time",     "profile",
                                                 "velocity", "time_factor", "ramp_time",     "factor_offset",
                                                 "factor_amplitude", "factor_period"};
// The keys each side kind accepts (a subset of wall_keys).
inline constexpr std::string_view wall_side_keys[] = {"kind", "speed", "stop_time"};
inline constexpr std::string_view inflow_side_keys[] = {"kind",      "profile",       "velocity",
                                                        "time_factor", "ramp_time",   "factor_offset",
                                                        "factor_amplitude", "factor_period"};
inline constexpr std::string_view open_side_keys[] = {"kind"};  // outflow, periodic
std::span<const std::string_view> keys_of_side_kind(WallSpec::Kind kind);
inline constexpr std::string_view ibm_keys[] = {"kernel", "forcing_passes", "forcing_stage",
                                                "inner_fluid_inertia", "sub_markers", "marker_retraction",
                                                "coupling", "slip_tolerance", "max_coupling_iterations", "preconditioner_drift",
                                                "constrained_velocity", "virtual_mass_coefficient", "rigid_response",
                                                "rim_preconditioner"};
inline constexpr std::string_view body_keys[] = {
    "kind",          "centre",           "velocity",       "angular_velocity",
    "diameter",      "n_surface_points", "density",        "spring_stiffness",
    "spring_damping", "restitution_coefficient", "cross_springs", "mass_lumping", "spring_integrator",
    "swelling",      "oscillation_amplitude", "angle_amplitude", "oscillation_period",
    "oscillation_phase", "reference_speed", "reference_length"};
// The keys each body kind accepts (a subset of body_keys); any other key is an error naming the kind.
inline constexpr std::string_view mass_spring_body_keys[] = {
    "kind",          "centre",           "velocity",       "angular_velocity",
    "diameter",      "n_surface_points", "density",        "spring_stiffness",
    "spring_damping", "restitution_coefficient", "cross_springs", "mass_lumping", "spring_integrator",
    "swelling",      "reference_speed",  "reference_length"};
inline constexpr std::string_view rigid_body_keys[] = {
    "kind", "centre", "velocity", "angular_velocity", "diameter", "n_surface_points", "density",
    "reference_speed", "reference_length"};
inline constexpr std::string_view prescribed_body_keys[] = {
    "kind", "centre", "velocity", "angular_velocity", "diameter", "n_surface_points",
    "oscillation_amplitude", "angle_amplitude", "oscillation_period", "oscillation_phase",
    "reference_speed", "reference_length"};
inline constexpr std::string_view swelling_keys[] = {"onset_time", "rate", "max_diameter"};
inline constexpr std::string_view contact_keys[] = {"stiffness", "restitution_coefficient",
                                                    "cds_radius", "cds_radius_fraction", "walls", "centre_point",
                                                    "time_stepping", "inner_step", "outer_step_fraction", "model",
                                                    "collision_steps"};
inline constexpr std::string_view output_keys[] = {"file", "series_every", "snapshot_interval",
                                                   "centreline_profiles", "progress", "checkpoint_every",
                                                   "probes"};

// One scene name of an enum value, and Choices<Enum>::table: every value of the enum with its scene
// name, in the order messages list them. The options the modules act on have their tables beside
// their enums (core/options.hpp); those below are read by the simulation alone.
template <class Enum>
using Choice = OptionName<Enum>;
template <class Enum>
using Choices = OptionNames<Enum>;

}  // namespace ibms::scene_schema

namespace ibms {

IBMS_OPTION_NAMES(RunSpec::SolidSubsteps, {RunSpec::SolidSubsteps::per_group, "per_group"},
                   {RunSpec::SolidSubsteps::global, "global"});
// run.on_body_instability and run.on_fluid_instability.
IBMS_OPTION_NAMES(RunSpec::OnInstability, {RunSpec::OnInstability::stop, "stop"},
                   {RunSpec::OnInstability::warn, "warn"});
IBMS_OPTION_NAMES(FluidSpec::WallClosure, {FluidSpec::WallClosure::linear, "linear"},
                   {FluidSpec::WallClosure::quadratic, "quadratic"});
IBMS_OPTION_NAMES(IbmSpec::ForcingStage, {IbmSpec::ForcingStage::explicit_estimate, "explicit_estimate"},
                   {IbmSpec::ForcingStage::implicit_prediction, "implicit_prediction"});
IBMS_OPTION_NAMES(IbmSpec::InnerFluidInertia, {IbmSpec::InnerFluidInertia::kempe, "kempe"},
                   {IbmSpec::InnerFluidInertia::none, "none"},
                   {IbmSpec::InnerFluidInertia::kempe_by_mass, "kempe_by_mass"});
IBMS_OPTION_NAMES(IbmSpec::Coupling, {IbmSpec::Coupling::uhlmann, "uhlmann"},
                   {IbmSpec::Coupling::no_slip, "no_slip"});
IBMS_OPTION_NAMES(IbmSpec::ConstrainedVelocity, {IbmSpec::ConstrainedVelocity::cells, "cells"},
                   {IbmSpec::ConstrainedVelocity::faces, "faces"});
IBMS_OPTION_NAMES(IbmSpec::RigidResponse, {IbmSpec::RigidResponse::implicit, "implicit"},
                   {IbmSpec::RigidResponse::virtual_mass, "virtual_mass"});
IBMS_OPTION_NAMES(IbmSpec::RimPreconditioner, {IbmSpec::RimPreconditioner::identity, "identity"},
                   {IbmSpec::RimPreconditioner::response, "response"});
IBMS_OPTION_NAMES(ContactSpec::TimeStepping, {ContactSpec::TimeStepping::inner_loop, "inner_loop"},
                   {ContactSpec::TimeStepping::shared, "shared"});

}  // namespace ibms

namespace ibms::scene_schema {


// The scene names of an enum's values, in table order (for "must be one of ..." messages).
template <class Enum>
inline constexpr auto choice_names = [] {
  constexpr auto& table = Choices<Enum>::table;
  std::array<std::string_view, std::size(table)> names{};
  for (std::size_t k = 0; k < names.size(); ++k) names[k] = table[k].name;
  return names;
}();

// The scene name of a value (every enumerator is in its table).
template <class Enum>
constexpr std::string_view name_of(Enum value) {
  return option_name(value);
}

// The value a scene name stands for; empty for a name not in the table.
template <class Enum>
constexpr std::optional<Enum> parse_choice(std::string_view name) {
  for (const Choice<Enum>& choice : Choices<Enum>::table)
    if (choice.name == name) return choice.value;
  return std::nullopt;
}

// Keys a body of this kind accepts.
std::span<const std::string_view> keys_of_body_kind(BodySpec::Kind kind);

// Keys of a plain section (run, domain, fluid, ibm, contact, output); empty for walls/bodies.
std::span<const std::string_view> keys_of_section(std::string_view section);

// The allowed name closest to `name` when it is a plausible misspelling, else "".
std::string closest_name(std::string_view name, std::span<const std::string_view> allowed);

// ", did you mean 'x'?" or "" — appended to unknown-key messages.
std::string suggestion_suffix(std::string_view name, std::span<const std::string_view> allowed);

// "a, b, c" for messages.
std::string join_names(std::span<const std::string_view> names);

}  // namespace ibms::scene_schema
