// Body geometry diagnostics (see body_geometry.hpp).
#include "solid/body_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ibms {

namespace {

// Even-odd rule point-in-polygon test on the rim polygon of `body`.
bool inside_rim(const MassSpringBody& body, const std::array<double, 2>& p) {
  bool inside = false;
  for (int a = 0, b = body.n_surface - 1; a < body.n_surface; b = a++) {
    const auto& pa = body.position[a];
    const auto& pb = body.position[b];
    if ((pa[1] > p[1]) != (pb[1] > p[1]) &&
        p[0] < (pb[0] - pa[0]) * (p[1] - pa[1]) / (pb[1] - pa[1]) + pa[0])
      inside = !inside;
  }
  return inside;
}

}  // namespace

double deformation_parameter(const MassSpringBody& body) {
  const std::array<double, 2> c = centroid(body);
  double r_min = std::numeric_limits<double>::infinity(), r_max = 0.0;
  for (int l = 0; l < body.n_surface; ++l) {
    const double r = std::hypot(body.position[l][0] - c[0], body.position[l][1] - c[1]);
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
  }
  return (r_max - r_min) / (r_max + r_min);
}

BodySeparation body_separation(const std::vector<MassSpringBody>& bodies, std::array<double, 2> lower,
                               std::array<double, 2> upper, std::array<bool, 2> periodic) {
  BodySeparation s;
  s.min_rim_distance = std::numeric_limits<double>::infinity();
  s.min_wall_distance = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    const MassSpringBody& A = bodies[a];
    for (int l = 0; l < A.n_surface; ++l) {
      const auto& p = A.position[l];
      for (int d = 0; d < 2; ++d)
        if (!periodic[d]) s.min_wall_distance = std::min({s.min_wall_distance, p[d] - lower[d], upper[d] - p[d]});
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (b == a) continue;
        const MassSpringBody& B = bodies[b];
        if (b > a)
          for (int m = 0; m < B.n_surface; ++m)
            s.min_rim_distance =
                std::min(s.min_rim_distance, std::hypot(B.position[m][0] - p[0], B.position[m][1] - p[1]));
        if (inside_rim(B, p)) ++s.n_points_inside_others;
      }
    }
  }
  return s;
}

}  // namespace ibms
