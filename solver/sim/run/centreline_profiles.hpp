// Centre-line profiles of the velocity (the cavity cases' output and checks).
#pragma once
#include <vector>

#include "sim/simulation.hpp"

namespace ibms {

// Velocity along the vertical centre line (u against y) and the horizontal one (v against x),
// wall values included at both ends; linear interpolation between the two central cells.
struct CentrelineProfiles {
  std::vector<double> y, u;   // x = mid-width
  std::vector<double> x, v;   // y = mid-height
};
CentrelineProfiles centreline_profiles(const Simulation& sim);

}  // namespace ibms
