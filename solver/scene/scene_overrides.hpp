// Command-line overrides `--set dotted.key=value` applied to a parsed scene before validation
// (docs/design.md §4), so convergence sweeps need no copies of scene files. `bodies.<index>.key`
// addresses one [[bodies]] entry. The value is read as a TOML value, else taken as a string.
#pragma once
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scene/scene_diagnostics.hpp"

namespace ibms {

// Applies each "key=value" in order; a key outside the schema is an error naming "--set <text>".
void apply_scene_overrides(toml::table& root, const std::vector<std::string>& overrides,
                           SceneDiagnostics& diagnostics);

}  // namespace ibms
