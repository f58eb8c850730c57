// Triangle-cell overlap areas by Sutherland-Hodgman clipping (see triangle_cell_overlap.hpp).
#include "ibm/triangle_cell_overlap.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {
namespace {

// A convex polygon of at most 3 + 4 vertices (a square clipped by three half-planes).
struct SmallPolygon {
  std::array<std::array<double, 2>, 8> vertex{};
  int n = 0;
};

// Keeps the part of `in` on the left of the directed line p -> q (cross >= 0).
SmallPolygon clip_left_of(const SmallPolygon& in, const std::array<double, 2>& p,
                          const std::array<double, 2>& q) {
  SmallPolygon out;
  const double ex = q[0] - p[0], ey = q[1] - p[1];
  auto side = [&](const std::array<double, 2>& v) { return ex*(v[1] - p[1]) - ey*(v[0] - p[0]); };
  for (int k = 0; k < in.n; ++k) {
    const auto& cur = in.vertex[k];
    const auto& nxt = in.vertex[(k + 1) % in.n];
    const double s_cur = side(cur), s_nxt = side(nxt);
    if (s_cur >= 0) out.vertex[out.n++] = cur;
    if ((s_cur >= 0) != (s_nxt >= 0)) {  // the edge crosses the line: add the crossing
      const double w = s_cur / (s_cur - s_nxt);
      out.vertex[out.n++] = {cur[0] + w*(nxt[0] - cur[0]), cur[1] + w*(nxt[1] - cur[1])};
    }
  }
  return out;
}

// Shoelace relative to the first vertex (coordinates O(h), not O(box), keep the round-off small).
double shoelace_area(const SmallPolygon& poly) {
  double twice = 0.0;
  const auto& o = poly.vertex[0];
  for (int k = 1; k + 1 < poly.n; ++k) {
    const double ax = poly.vertex[k][0] - o[0], ay = poly.vertex[k][1] - o[1];
    const double bx = poly.vertex[k + 1][0] - o[0], by = poly.vertex[k + 1][1] - o[1];
    twice += ax*by - bx*ay;
  }
  return 0.5 * twice;
}

int wrap(int index, int n) { return ((index % n) + n) % n; }

}  // namespace

void add_triangle_cell_overlaps(const Grid& grid, const std::array<double, 2>& a,
                                const std::array<double, 2>& b, const std::array<double, 2>& c,
                                std::vector<CellOverlap>& overlaps) {
  // Counter-clockwise vertex order, so "inside" is on the left of every edge.
  const double orientation = (b[0] - a[0])*(c[1] - a[1]) - (b[1] - a[1])*(c[0] - a[0]);
  if (orientation == 0.0) return;  // degenerate triangle: no area
  const std::array<std::array<double, 2>, 3> tri =
      orientation > 0 ? std::array<std::array<double, 2>, 3>{a, b, c} : std::array<std::array<double, 2>, 3>{a, c, b};
  const double dx = grid.dx(), dy = grid.dy();
  const double x_min = std::min({a[0], b[0], c[0]}), x_max = std::max({a[0], b[0], c[0]});
  const double y_min = std::min({a[1], b[1], c[1]}), y_max = std::max({a[1], b[1], c[1]});
  int i0 = static_cast<int>(std::floor((x_min - grid.origin_x) / dx));
  int i1 = static_cast<int>(std::floor((x_max - grid.origin_x) / dx));
  int j0 = static_cast<int>(std::floor((y_min - grid.origin_y) / dy));
  int j1 = static_cast<int>(std::floor((y_max - grid.origin_y) / dy));
  if (!grid.periodic_x) { i0 = std::max(i0, 0); i1 = std::min(i1, grid.nx - 1); }
  if (!grid.periodic_y) { j0 = std::max(j0, 0); j1 = std::min(j1, grid.ny - 1); }
  for (int j = j0; j <= j1; ++j) {
    // The triangle's x-extent within this row band [y_lo, y_hi]: the ends of its edges clipped
    // to the band. Only the cells of that extent are visited (cost ~ overlapped cells, not bbox).
    const double y_lo = grid.origin_y + j*dy, y_hi = y_lo + dy;
    double row_min = HUGE_VAL, row_max = -HUGE_VAL;
    for (int e = 0; e < 3; ++e) {
      const auto& p = tri[e];
      const auto& q = tri[(e + 1) % 3];
      const double t_lo = p[1] == q[1] ? (p[1] >= y_lo && p[1] <= y_hi ? 0.0 : HUGE_VAL) : 0.0;
      if (t_lo == HUGE_VAL) continue;
      double s0 = 0.0, s1 = 1.0;  // parameter range of the edge inside the band
      if (p[1] != q[1]) {
        const double sa = (y_lo - p[1]) / (q[1] - p[1]), sb = (y_hi - p[1]) / (q[1] - p[1]);
        s0 = std::max(s0, std::min(sa, sb));
        s1 = std::min(s1, std::max(sa, sb));
        if (s0 > s1) continue;
      }
      for (const double w : {s0, s1}) {
        const double x = p[0] + w*(q[0] - p[0]);
        row_min = std::min(row_min, x);
        row_max = std::max(row_max, x);
      }
    }
    if (!(row_min <= row_max)) continue;
    int row_i0 = std::max(i0, static_cast<int>(std::floor((row_min - grid.origin_x) / dx)));
    int row_i1 = std::min(i1, static_cast<int>(std::floor((row_max - grid.origin_x) / dx)));
    for (int i = row_i0; i <= row_i1; ++i) {
      // The unwrapped cell square (periodic images are clipped where the triangle is).
      const double x0 = grid.origin_x + i*dx, y0 = grid.origin_y + j*dy;
      // Quick classification by the four corners: outside one edge -> no overlap; inside all
      // three -> the whole cell. Only cells the triangle's edges cross are clipped.
      bool outside = false, inside = true;
      for (int e = 0; e < 3 && !outside; ++e) {
        const auto& p = tri[e];
        const auto& q = tri[(e + 1) % 3];
        const double ex = q[0] - p[0], ey = q[1] - p[1];
        int n_inside = 0;
        for (const double cx : {x0, x0 + dx})
          for (const double cy : {y0, y0 + dy}) n_inside += ex*(cy - p[1]) - ey*(cx - p[0]) >= 0 ? 1 : 0;
        outside = n_inside == 0;
        inside = inside && n_inside == 4;
      }
      if (outside) continue;
      if (inside) {
        overlaps.push_back({wrap(i, grid.nx), wrap(j, grid.ny), dx*dy});
        continue;
      }
      SmallPolygon poly;
      poly.n = 4;
      poly.vertex[0] = {x0, y0};
      poly.vertex[1] = {x0 + dx, y0};
      poly.vertex[2] = {x0 + dx, y0 + dy};
      poly.vertex[3] = {x0, y0 + dy};
      for (int e = 0; e < 3 && poly.n > 0; ++e) poly = clip_left_of(poly, tri[e], tri[(e + 1) % 3]);
      if (poly.n < 3) continue;
      const double area = shoelace_area(poly);
      if (area > 0.0) overlaps.push_back({wrap(i, grid.nx), wrap(j, grid.ny), area});
    }
  }
}

}  // namespace ibms
