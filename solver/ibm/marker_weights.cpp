// Marker volume weights dV_l = h s_l of METHOD.md §3.6.
#include "ibm/marker_weights.hpp"

#include <cmath>
#include <stdexcept>

namespace ibms {

std::vector<double> marker_weights(const std::vector<std::array<double, 2>>& closed_ring,
                                   double h) {
  const std::size_t n = closed_ring.size();
  if (n < 3) throw std::invalid_argument("marker_weights: a closed ring needs >= 3 markers");
  if (!(h > 0.0)) throw std::invalid_argument("marker_weights: grid spacing must be > 0");
  // segment[l] = |X_{l+1} - X_l|
  std::vector<double> segment(n);
  for (std::size_t l = 0; l < n; ++l) {
    const auto& a = closed_ring[l];
    const auto& b = closed_ring[(l + 1) % n];
    segment[l] = std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  std::vector<double> volume(n);
  for (std::size_t l = 0; l < n; ++l)
    volume[l] = h * 0.5 * (segment[l] + segment[(l + n - 1) % n]);
  return volume;
}

}  // namespace ibms
