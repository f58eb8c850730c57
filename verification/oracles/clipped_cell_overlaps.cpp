// Triangle-cell overlaps by clipping (clipped_cell_overlaps.hpp).
#include "oracles/clipped_cell_overlaps.hpp"

#include <algorithm>
#include <cmath>

namespace ibms::oracle {
namespace {

using Point = std::array<double, 2>;

// The part of a convex polygon on the left of the directed line p -> q.
std::vector<Point> clip_left_of(const std::vector<Point>& in, const Point& p, const Point& q) {
  std::vector<Point> out;
  const auto side = [&](const Point& v) { return (q[0] - p[0]) * (v[1] - p[1]) - (q[1] - p[1]) * (v[0] - p[0]); };
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Point& cur = in[k];
    const Point& nxt = in[(k + 1) % in.size()];
    const double s_cur = side(cur), s_nxt = side(nxt);
    if (s_cur >= 0) out.push_back(cur);
    if ((s_cur >= 0) != (s_nxt >= 0)) {
      const double w = s_cur / (s_cur - s_nxt);
      out.push_back({cur[0] + w * (nxt[0] - cur[0]), cur[1] + w * (nxt[1] - cur[1])});
    }
  }
  return out;
}

double area(const std::vector<Point>& poly) {
  double twice = 0.0;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    twice += (poly[k][0] - poly[0][0]) * (poly[k + 1][1] - poly[0][1]) -
             (poly[k + 1][0] - poly[0][0]) * (poly[k][1] - poly[0][1]);
  return 0.5 * twice;
}

int wrap(int index, int n) { return ((index % n) + n) % n; }

}  // namespace

std::vector<CellOverlap> clipped_cell_overlaps(const Grid& grid, const Point& a, const Point& b, const Point& c) {
  std::vector<CellOverlap> out;
  const double orientation = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (orientation == 0.0) return out;
  const std::array<Point, 3> tri = orientation > 0 ? std::array<Point, 3>{a, b, c} : std::array<Point, 3>{a, c, b};
  const double dx = grid.dx(), dy = grid.dy();
  int i0 = static_cast<int>(std::floor((std::min({a[0], b[0], c[0]}) - grid.origin_x) / dx));
  int i1 = static_cast<int>(std::floor((std::max({a[0], b[0], c[0]}) - grid.origin_x) / dx));
  int j0 = static_cast<int>(std::floor((std::min({a[1], b[1], c[1]}) - grid.origin_y) / dy));
  int j1 = static_cast<int>(std::floor((std::max({a[1], b[1], c[1]}) - grid.origin_y) / dy));
  if (!grid.periodic_x) { i0 = std::max(i0, 0); i1 = std::min(i1, grid.nx - 1); }
  if (!grid.periodic_y) { j0 = std::max(j0, 0); j1 = std::min(j1, grid.ny - 1); }
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x0 = grid.origin_x + i * dx, y0 = grid.origin_y + j * dy;
      std::vector<Point> poly{{x0, y0}, {x0 + dx, y0}, {x0 + dx, y0 + dy}, {x0, y0 + dy}};
      for (int e = 0; e < 3 && poly.size() >= 3; ++e) poly = clip_left_of(poly, tri[e], tri[(e + 1) % 3]);
      if (poly.size() < 3) continue;
      const double s = area(poly);
      if (s > 0.0) out.push_back({wrap(i, grid.nx), wrap(j, grid.ny), s});
    }
  return out;
}

}  // namespace ibms::oracle
