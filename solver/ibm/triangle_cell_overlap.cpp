// Triangle-cell overlap areas as sums of edge integrals (see triangle_cell_overlap.hpp).
#include "ibm/triangle_cell_overlap.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {
namespace {

// The mean over a segment of g(y) = clamp(y, y0, y0 + height) - y0, y running linearly from lo to
// hi (lo <= hi): (G(hi) - G(lo)) / (hi - lo) with G the antiderivative of g, each case written
// without the cancellation of the plain difference (the terms added are all non-negative).
double mean_in_band(double lo, double hi, double y0, double height) {
  const double y1 = y0 + height;
  if (hi <= y0) return 0.0;
  if (lo >= y1) return height;
  if (lo >= y0 && hi <= y1) return 0.5 * (lo + hi) - y0;
  const double span = hi - lo;  // > 0: lo and hi lie in different parts of g
  if (lo < y0 && hi <= y1) return 0.5 * (hi - y0) * (hi - y0) / span;
  if (lo >= y0) return (height * (hi - y1) + 0.5 * (y1 - lo) * (y1 + lo - 2.0 * y0)) / span;  // hi > y1
  return (0.5 * height * height + height * (hi - y1)) / span;  // lo < y0, hi > y1
}

// An edge p -> q of a polygon, its x-range, slope and direction computed once for the cells it
// crosses. share(): minus the integral along the edge, over its part with x in [x0, x0 + width], of
// g(y) dx: the edge's share of the overlap of a counter-clockwise polygon with the box
// [x0, x0 + width] x [y0, y0 + height] (the sum over the polygon's edges: the lower edges run right,
// the upper ones left).
struct PreparedEdge {
  std::array<double, 2> p;
  double left = 0.0, right = 0.0, slope = 0.0, sign = 0.0;  // sign 0: vertical, no x extent
  PreparedEdge(const std::array<double, 2>& from, const std::array<double, 2>& to) : p(from) {
    if (from[0] == to[0]) return;
    const bool rightward = to[0] > from[0];
    left = rightward ? from[0] : to[0];
    right = rightward ? to[0] : from[0];
    slope = (to[1] - from[1]) / (to[0] - from[0]);
    sign = rightward ? -1.0 : 1.0;
  }
  double share(double x0, double width, double y0, double height) const {
    if (sign == 0.0) return 0.0;
    const double a = std::max(left, x0), b = std::min(right, x0 + width);
    if (a >= b) return 0.0;
    const double y_left = p[1] + (a - p[0]) * slope, y_right = p[1] + (b - p[0]) * slope;
    return sign * (b - a) * mean_in_band(std::min(y_left, y_right), std::max(y_left, y_right), y0, height);
  }
};

int wrap(int index, int n) { return index >= 0 && index < n ? index : ((index % n) + n) % n; }

}  // namespace

void add_triangle_cell_overlaps(const Grid& grid, const std::array<double, 2>& a,
                                const std::array<double, 2>& b, const std::array<double, 2>& c,
                                std::vector<CellOverlap>& overlaps) {
  // Counter-clockwise vertex order, so that the edge shares add up to the overlap.
  const double orientation = (b[0] - a[0])*(c[1] - a[1]) - (b[1] - a[1])*(c[0] - a[0]);
  if (orientation == 0.0) return;  // degenerate triangle: no area
  const std::array<std::array<double, 2>, 3> tri =
      orientation > 0 ? std::array<std::array<double, 2>, 3>{a, b, c} : std::array<std::array<double, 2>, 3>{a, c, b};
  const std::array<PreparedEdge, 3> edges{PreparedEdge(tri[0], tri[1]), PreparedEdge(tri[1], tri[2]),
                                           PreparedEdge(tri[2], tri[0])};
  const double dx = grid.dx(), dy = grid.dy(), cell_area = dx * dy;
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
      double s0 = 0.0, s1 = 1.0;  // parameter range of the edge inside the band
      if (p[1] == q[1]) {
        if (p[1] < y_lo || p[1] > y_hi) continue;
      } else {
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
    const int row_i0 = std::max(i0, static_cast<int>(std::floor((row_min - grid.origin_x) / dx)));
    const int row_i1 = std::min(i1, static_cast<int>(std::floor((row_max - grid.origin_x) / dx)));
    for (int i = row_i0; i <= row_i1; ++i) {
      // The unwrapped cell square (periodic images are covered where the triangle is): the overlap
      // as the sum of the edges' shares, the area between each edge and the band's floor within the
      // cell's columns (exact for a convex polygon; round-off kept inside [0, dx dy]).
      const double x0 = grid.origin_x + i*dx;
      double area = 0.0;
      for (const PreparedEdge& edge : edges) area += edge.share(x0, dx, y_lo, dy);
      if (area > 0.0) overlaps.push_back({wrap(i, grid.nx), wrap(j, grid.ny), std::min(area, cell_area)});
    }
  }
}

void add_polygon_cell_overlaps(const Grid& grid, const std::array<double, 2>* vertices, std::size_t n,
                               std::vector<CellOverlap>& overlaps, PolygonOverlapWork& work) {
  if (n < 3) return;
  double twice_area = 0.0;
  double x_min = HUGE_VAL, x_max = -HUGE_VAL, y_min = HUGE_VAL, y_max = -HUGE_VAL;
  for (std::size_t k = 0; k < n; ++k) {
    const auto& a = vertices[k];
    const auto& b = vertices[(k + 1) % n];
    twice_area += a[0] * b[1] - b[0] * a[1];
    x_min = std::min(x_min, a[0]);
    x_max = std::max(x_max, a[0]);
    y_min = std::min(y_min, a[1]);
    y_max = std::max(y_max, a[1]);
  }
  if (twice_area == 0.0) return;
  const double orientation = twice_area > 0.0 ? 1.0 : -1.0;  // the shares below are counter-clockwise
  const double dx = grid.dx(), dy = grid.dy(), cell_area = dx * dy;
  const int i0 = static_cast<int>(std::floor((x_min - grid.origin_x) / dx));
  const int i1 = static_cast<int>(std::floor((x_max - grid.origin_x) / dx));
  const int j0 = static_cast<int>(std::floor((y_min - grid.origin_y) / dy));
  const int j1 = static_cast<int>(std::floor((y_max - grid.origin_y) / dy));
  const int columns = i1 - i0 + 1, rows = j1 - j0 + 1;
  const std::size_t cells = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
  if (work.partial.size() < cells) {
    work.partial.resize(cells);
    work.full.resize(cells);
  }
  std::fill(work.partial.begin(), work.partial.begin() + static_cast<std::ptrdiff_t>(cells), 0.0);
  std::fill(work.full.begin(), work.full.begin() + static_cast<std::ptrdiff_t>(cells), 0.0);
  const auto at = [columns](int i, int j) { return static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i); };
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = orientation > 0.0 ? vertices[k] : vertices[(k + 1) % n];
    const auto& q = orientation > 0.0 ? vertices[(k + 1) % n] : vertices[k];
    if (p[0] == q[0]) continue;  // vertical: no x extent
    const double left = std::min(p[0], q[0]), right = std::max(p[0], q[0]);
    const int c0 = std::max(0, static_cast<int>(std::floor((left - grid.origin_x) / dx)) - i0);
    const int c1 = std::min(columns - 1, static_cast<int>(std::floor((right - grid.origin_x) / dx)) - i0);
    const double slope = (q[1] - p[1]) / (q[0] - p[0]);
    const double sign = q[0] > p[0] ? -1.0 : 1.0;
    for (int c = c0; c <= c1; ++c) {
      const double x0 = grid.origin_x + (i0 + c) * dx;
      const double a = std::max(left, x0), b = std::min(right, x0 + dx);
      if (a >= b) continue;
      const double ya = p[1] + (a - p[0]) * slope, yb = p[1] + (b - p[0]) * slope;
      const double lo = std::min(ya, yb), hi = std::max(ya, yb);
      // Rows the edge's y-range crosses take their share; the rows below it, the full band, carried
      // down from the first of them.
      const int r_lo = std::clamp(static_cast<int>(std::floor((lo - grid.origin_y) / dy)) - j0, 0, rows - 1);
      const int r_hi = std::clamp(static_cast<int>(std::floor((hi - grid.origin_y) / dy)) - j0, 0, rows - 1);
      for (int r = r_lo; r <= r_hi; ++r) {
        const double y0 = grid.origin_y + (j0 + r) * dy;
        work.partial[at(c, r)] += sign * (b - a) * mean_in_band(lo, hi, y0, dy);
      }
      if (r_lo > 0) work.full[at(c, r_lo - 1)] += sign * (b - a) * dy;
    }
  }
  for (int c = 0; c < columns; ++c) {
    double carried = 0.0;
    for (int r = rows - 1; r >= 0; --r) {
      carried += work.full[at(c, r)];
      const double area = work.partial[at(c, r)] + carried;
      if (!(area > 1e-12 * cell_area)) continue;
      const int i = i0 + c, j = j0 + r;
      if (!grid.periodic_x && (i < 0 || i >= grid.nx)) continue;
      if (!grid.periodic_y && (j < 0 || j >= grid.ny)) continue;
      overlaps.push_back({wrap(i, grid.nx), wrap(j, grid.ny), std::min(area, cell_area)});
    }
  }
}

}  // namespace ibms
