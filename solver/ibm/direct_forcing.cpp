// F_l = (U_target_l - U_interp_l) / dt, Uhlmann (2005) eq. (14), docs/method.md §3.1 step 3.
#include "ibm/direct_forcing.hpp"

#include <stdexcept>

namespace ibms {

void direct_forcing(const std::vector<std::array<double, 2>>& target_velocity,
                    const std::vector<std::array<double, 2>>& interpolated_velocity, double dt,
                    std::vector<std::array<double, 2>>& marker_force) {
  if (target_velocity.size() != interpolated_velocity.size())
    throw std::invalid_argument("direct_forcing: target and interpolated velocities differ in length");
  if (!(dt > 0.0)) throw std::invalid_argument("direct_forcing: dt must be > 0");
  marker_force.resize(target_velocity.size());
  for (std::size_t l = 0; l < target_velocity.size(); ++l)
    for (int c = 0; c < 2; ++c)
      marker_force[l][c] = (target_velocity[l][c] - interpolated_velocity[l][c]) / dt;
}

}  // namespace ibms
