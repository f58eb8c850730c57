// The scene schema: which sections and keys a scene may contain (docs/design.md §4). One list serves
// the reader (unknown-key errors), the `--set` overrides (key validation) and the suggestions
// for misspelt keys, so the three can never disagree. Key names equal the fields in scene.hpp.
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace ibms::scene_schema {

// Top-level sections in the order a scene lists them.
inline constexpr std::string_view section_names[] = {"run",    "domain", "fluid",   "walls",
                                                     "ibm",    "bodies", "contact", "output"};
inline constexpr std::string_view run_keys[] = {"end_time",         "time_step", "cfl",
                                                "max_time_step",    "steady_tolerance",
                                                "max_steps",        "max_cfl",
                                                "max_viscous_number", "solid_substeps", "on_body_instability",
                                                "on_fluid_instability"};
inline constexpr std::string_view on_body_instability_choices[] = {"stop", "warn"};
inline constexpr std::string_view on_fluid_instability_choices[] = {"stop", "warn"};
inline constexpr std::string_view solid_substeps_choices[] = {"per_group", "global"};
inline constexpr std::string_view domain_keys[] = {"length_x", "length_y",   "cells_x",
                                                   "cells_y",  "periodic_x", "periodic_y"};
inline constexpr std::string_view fluid_keys[] = {"density", "kinematic_viscosity", "gravity", "convection",
                                                  "wall_closure"};
inline constexpr std::string_view convection_choices[] = {"central", "quick"};
inline constexpr std::string_view wall_closure_choices[] = {"linear", "quadratic"};
inline constexpr std::string_view wall_names[] = {"left", "right", "bottom", "top"};
inline constexpr std::string_view wall_keys[] = {"kind",     "speed",       "stop_time",     "profile",
                                                 "velocity", "time_factor", "ramp_time",     "factor_offset",
                                                 "factor_amplitude", "factor_period"};
// The keys each side kind accepts (a subset of wall_keys).
inline constexpr std::string_view side_kind_choices[] = {"wall", "inflow", "outflow", "periodic"};
inline constexpr std::string_view wall_side_keys[] = {"kind", "speed", "stop_time"};
inline constexpr std::string_view inflow_side_keys[] = {"kind",      "profile",       "velocity",
                                                        "time_factor", "ramp_time",   "factor_offset",
                                                        "factor_amplitude", "factor_period"};
inline constexpr std::string_view open_side_keys[] = {"kind"};  // outflow, periodic
inline constexpr std::string_view inflow_profile_choices[] = {"uniform", "parabolic"};
inline constexpr std::string_view time_factor_choices[] = {"constant", "ramp", "sinusoidal"};
std::span<const std::string_view> keys_of_side_kind(std::string_view kind);
inline constexpr std::string_view ibm_keys[] = {"kernel", "forcing_passes", "forcing_stage",
                                                "inner_fluid_inertia", "sub_markers", "marker_retraction",
                                                "coupling", "slip_tolerance", "max_coupling_iterations",
                                                "constrained_velocity", "virtual_mass_coefficient"};
inline constexpr std::string_view coupling_choices[] = {"uhlmann", "no_slip"};
inline constexpr std::string_view constrained_velocity_choices[] = {"cells", "faces"};
inline constexpr std::string_view forcing_stage_choices[] = {"explicit_estimate", "implicit_prediction"};
inline constexpr std::string_view body_keys[] = {
    "kind",          "centre",           "velocity",       "angular_velocity",
    "diameter",      "n_surface_points", "density",        "spring_stiffness",
    "spring_damping", "restitution_coefficient", "cross_springs", "mass_lumping", "spring_integrator",
    "swelling",      "oscillation_amplitude", "angle_amplitude", "oscillation_period",
    "oscillation_phase", "reference_speed", "reference_length"};
// The keys each body kind accepts (a subset of body_keys); any other key is an error naming the kind.
inline constexpr std::string_view body_kind_choices[] = {"mass_spring", "rigid", "prescribed"};
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
                                                    "cds_radius", "cds_radius_fraction", "walls",
                                                    "time_stepping", "model", "collision_steps"};
inline constexpr std::string_view contact_time_stepping_choices[] = {"inner_loop", "shared"};
inline constexpr std::string_view contact_model_choices[] = {"linear", "collision_time"};
inline constexpr std::string_view output_keys[] = {"file", "series_every", "snapshot_interval",
                                                   "centreline_profiles", "progress", "checkpoint_every",
                                                   "probes"};

inline constexpr std::string_view kernel_choices[] = {"roma3", "peskin4", "cosine4", "bkp6"};
inline constexpr std::string_view inner_fluid_inertia_choices[] = {"kempe", "none"};
inline constexpr std::string_view mass_lumping_choices[] = {"equal", "uniform_disk"};
inline constexpr std::string_view spring_integrator_choices[] = {"auto", "explicit", "implicit"};

// Keys a body of this kind accepts (empty for an unknown kind).
std::span<const std::string_view> keys_of_body_kind(std::string_view kind);

// Keys of a plain section (run, domain, fluid, ibm, contact, output); empty for walls/bodies.
std::span<const std::string_view> keys_of_section(std::string_view section);

// The allowed name closest to `name` when it is a plausible misspelling, else "".
std::string closest_name(std::string_view name, std::span<const std::string_view> allowed);

// ", did you mean 'x'?" or "" — appended to unknown-key messages.
std::string suggestion_suffix(std::string_view name, std::span<const std::string_view> allowed);

// "a, b, c" for messages.
std::string join_names(std::span<const std::string_view> names);

}  // namespace ibms::scene_schema
