// Direct-forcing Lagrangian force, Uhlmann (2005) eq. (14) / docs/method.md §3.1 step 3, §3.5 step 2:
// F_l = (U_target_l - U_interp_l) / dt  [length/time^2], an acceleration applied to the fluid.
#pragma once
#include <array>
#include <vector>

namespace ibms {

void direct_forcing(const std::vector<std::array<double, 2>>& target_velocity,
                    const std::vector<std::array<double, 2>>& interpolated_velocity, double dt,
                    std::vector<std::array<double, 2>>& marker_force);

}  // namespace ibms
