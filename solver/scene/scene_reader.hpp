// TOML scene -> validated, typed Scene (docs/design.md §4). All input checks live here: unknown keys,
// wrong types, missing required keys, values out of range, bodies outside the box or overlapping,
// an unwritable output directory. Each failure throws InputError with ONE line:
//   "<file>:<line>:<col>: <key path>: <reason>"  (or "<file>: <key path>: <reason>" without a place).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ibms {

// Reads the scene file at `path`, applies `overrides` ("dotted.key=value", e.g.
// "bodies.0.diameter=0.3") and validates. Sets Scene::source_file and Scene::resolved_text.
Scene read_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for scene text; `source_name` stands for the file in messages.
Scene read_scene_string(const std::string& toml_text, const std::string& source_name,
                        const std::vector<std::string>& overrides = {});

// Full TOML of every key, defaults included, sections in the documented order; reading it
// back gives the same Scene. (spring_damping < 0, i.e. "from restitution", and a disabled
// swelling are written as comments, since the schema has no value that means "unset".)
std::string resolved_scene_toml(const Scene& scene);

}  // namespace ibms
