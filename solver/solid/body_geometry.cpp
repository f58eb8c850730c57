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
  using Vec = std::array<double, 2>;
  // Minimum image of an offset in the periodic directions (bodies are never wrapped: a body's
  // points stay within one period of each other, so one image per body pair is enough).
  auto image = [&](Vec d) {
    for (int c = 0; c < 2; ++c)
      if (periodic[c]) {
        const double length = upper[c] - lower[c];
        d[c] -= length * std::round(d[c] / length);
      }
    return d;
  };
  BodySeparation s;
  s.min_rim_distance = std::numeric_limits<double>::infinity();
  s.min_wall_distance = std::numeric_limits<double>::infinity();
  std::vector<Vec> centre(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) centre[b] = centroid(bodies[b]);
  // The image of a point of one body nearest to body b's centroid.
  auto near_image = [&](const Vec& p, std::size_t b) {
    const Vec d = image({p[0] - centre[b][0], p[1] - centre[b][1]});
    return Vec{centre[b][0] + d[0], centre[b][1] + d[1]};
  };
  for (std::size_t a = 0; a < bodies.size(); ++a) {
    const MassSpringBody& A = bodies[a];
    for (int l = 0; l < A.n_surface; ++l) {
      const Vec& p = A.position[l];
      for (int d = 0; d < 2; ++d)
        if (!periodic[d]) s.min_wall_distance = std::min({s.min_wall_distance, p[d] - lower[d], upper[d] - p[d]});
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (b == a) continue;
        const MassSpringBody& B = bodies[b];
        if (b > a)
          for (int m = 0; m < B.n_surface; ++m) {
            const Vec d = image({B.position[m][0] - p[0], B.position[m][1] - p[1]});
            s.min_rim_distance = std::min(s.min_rim_distance, std::hypot(d[0], d[1]));
          }
        if (inside_rim(B, near_image(p, b))) ++s.n_points_inside_others;
      }
    }
  }
  // Rim edges of different bodies that cross (interpenetration without a vertex inside).
  auto orientation = [](const Vec& o, const Vec& p, const Vec& q) {
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
  };
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const MassSpringBody& A = bodies[a];
      const MassSpringBody& B = bodies[b];
      for (int l = 0; l < A.n_surface; ++l) {
        const Vec p0 = near_image(A.position[l], b);
        const Vec p1 = {p0[0] + A.position[(l + 1) % A.n_surface][0] - A.position[l][0],
                        p0[1] + A.position[(l + 1) % A.n_surface][1] - A.position[l][1]};
        for (int m = 0; m < B.n_surface; ++m) {
          const Vec& q0 = B.position[m];
          const Vec& q1 = B.position[(m + 1) % B.n_surface];
          const double o1 = orientation(p0, p1, q0), o2 = orientation(p0, p1, q1);
          const double o3 = orientation(q0, q1, p0), o4 = orientation(q0, q1, p1);
          if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
            ++s.n_edge_crossings;
        }
      }
    }
  return s;
}

}  // namespace ibms
