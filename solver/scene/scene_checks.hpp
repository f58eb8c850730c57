// Scene checks that involve several keys (run after every key has been read on its own): the
// adaptive step's run.cfl below the guard run.max_cfl, wall speeds on periodic sides, bodies inside the box and not overlapping, contact radius,
// and a writable output directory.
#pragma once
#include "scene/scene.hpp"
#include "scene/scene_diagnostics.hpp"

namespace ibms {

// Throws InputError (via `diagnostics`, pointing at the offending key) on the first failure.
void check_scene_consistency(const Scene& scene, const SceneDiagnostics& diagnostics);

}  // namespace ibms
