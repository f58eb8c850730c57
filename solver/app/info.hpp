// `ibms info`: the resolved scene, the grid, the stages that will run, time-step limits and an
// estimate of the number of steps, as text.
#pragma once
#include <string>

#include "scene/scene.hpp"

namespace ibms {
std::string describe_scene(const Scene& scene);
}
