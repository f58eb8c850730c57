// The lattice Green's function of the five-point Laplacian (lattice_green_function.hpp).
#include "fluid/lattice_green_function.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace ibms {

void LatticeGreensFunction::ensure(double dx, double dy, int radius) {
  if (radius <= radius_ && dx == dx_ && dy == dy_) return;
  // Grown to at least twice the old reach, so that bodies asking one more cell at a time do not
  // rebuild it at every step.
  if (dx == dx_ && dy == dy_) radius = std::max(radius, 2 * radius_);
  dx_ = dx;
  dy_ = dy;
  radius_ = radius;
  const std::size_t width = static_cast<std::size_t>(radius + 1);
  table_.assign(width * width, 0.0);
  constexpr int points = 8192;
  const double step = pi / points, ratio = (dx * dx) / (dy * dy);
  std::vector<double> power(width);
  for (int q = 0; q < points; ++q) {
    const double eta = (q + 0.5) * step;
    const double s = ratio * (2.0 - 2.0 * std::cos(eta));
    const double lambda = 1.0 + 0.5 * s - std::sqrt(s + 0.25 * s * s);  // the root below 1
    const double weight = dx * dx / pi * step / (lambda - 1.0 / lambda);
    power[0] = 1.0;
    for (std::size_t m = 1; m < width; ++m) power[m] = power[m - 1] * lambda;
    for (std::size_t n = 0; n < width; ++n) {
      const double c = std::cos(static_cast<double>(n) * eta);
      double* row = table_.data() + n * width;
      for (std::size_t m = 0; m < width; ++m) row[m] += weight * (power[m] * c - 1.0);
    }
  }
}

}  // namespace ibms
