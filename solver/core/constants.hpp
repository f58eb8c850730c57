// Mathematical constants of the solver and its tests, one definition each.
#pragma once

namespace ibms {

inline constexpr double pi = 3.14159265358979323846;  // [-]

}  // namespace ibms
