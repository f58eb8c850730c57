// Marker volume weights dV_l = h s_l of docs/method.md §3.6.
#include "ibm/marker_weights.hpp"

#include <cmath>
#include <stdexcept>

namespace ibms {

void marker_weights(const std::vector<std::array<double, 2>>& closed_ring, double h, std::vector<double>& volume) {
  const std::size_t n = closed_ring.size();
  if (n < 3) throw std::invalid_argument("marker_weights: a closed ring needs >= 3 markers");
  if (!(h > 0.0)) throw std::invalid_argument("marker_weights: grid spacing must be > 0");
  volume.resize(n);
  // dV_l = h (|X_{l+1} - X_l| + |X_l - X_{l-1}|) / 2, one pass carrying the previous segment.
  auto segment = [&](std::size_t l) {
    const auto& a = closed_ring[l];
    const auto& b = closed_ring[(l + 1) % n];
    return std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  const double last = segment(n - 1);
  double previous = last;
  for (std::size_t l = 0; l < n; ++l) {
    const double current = l + 1 < n ? segment(l) : last;
    volume[l] = h * 0.5 * (current + previous);
    previous = current;
  }
}

std::vector<double> marker_weights(const std::vector<std::array<double, 2>>& closed_ring, double h) {
  std::vector<double> volume;
  marker_weights(closed_ring, h, volume);
  return volume;
}

}  // namespace ibms
