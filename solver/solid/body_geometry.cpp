// Body geometry diagnostics (see body_geometry.hpp).
#include "solid/body_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cell_hash.hpp"

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

namespace {

using Vec = std::array<double, 2>;

struct Box {
  Vec low, high;
};

Box rim_box(const MassSpringBody& body) {
  Box box{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
          {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}};
  for (int l = 0; l < body.n_surface; ++l)
    for (int d = 0; d < 2; ++d) {
      box.low[d] = std::min(box.low[d], body.position[l][d]);
      box.high[d] = std::max(box.high[d], body.position[l][d]);
    }
  return box;
}

// Distance from p to the box (0 inside).
double box_distance(const Box& box, const Vec& p) {
  const double dx = std::max({box.low[0] - p[0], 0.0, p[0] - box.high[0]});
  const double dy = std::max({box.low[1] - p[1], 0.0, p[1] - box.high[1]});
  return std::hypot(dx, dy);
}

// Gap between two boxes (0 when they touch or overlap).
double box_gap(const Box& a, const Box& b) {
  const double dx = std::max({b.low[0] - a.high[0], 0.0, a.low[0] - b.high[0]});
  const double dy = std::max({b.low[1] - a.high[1], 0.0, a.low[1] - b.high[1]});
  return std::hypot(dx, dy);
}

bool boxes_overlap(const Box& a, const Box& b) {
  return a.low[0] <= b.high[0] && b.low[0] <= a.high[0] && a.low[1] <= b.high[1] && b.low[1] <= a.high[1];
}

double orientation(const Vec& o, const Vec& p, const Vec& q) {
  return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
}

// The box of the edge p0-p1.
Box edge_box(const Vec& p0, const Vec& p1) {
  return {{std::min(p0[0], p1[0]), std::min(p0[1], p1[1])}, {std::max(p0[0], p1[0]), std::max(p0[1], p1[1])}};
}

// Two edges p0-p1 and q0-q1 cross (properly: each separates the other's end points).
bool edges_cross(const Vec& p0, const Vec& p1, const Vec& q0, const Vec& q1) {
  const double o1 = orientation(p0, p1, q0), o2 = orientation(p0, p1, q1);
  const double o3 = orientation(q0, q1, p0), o4 = orientation(q0, q1, p1);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Pairs of non-adjacent edges of the rim that cross.
int rim_self_crossings(const MassSpringBody& body) {
  const int n = body.n_surface;
  int crossings = 0;
  for (int l = 0; l < n; ++l) {
    const Vec& p0 = body.position[l];
    const Vec& p1 = body.position[(l + 1) % n];
    const Box edge = edge_box(p0, p1);
    for (int m = l + 2; m < n; ++m) {
      if (l == 0 && m == n - 1) continue;  // the edge before l = 0 shares its point
      const Vec& q0 = body.position[m];
      const Vec& q1 = body.position[(m + 1) % n];
      if (boxes_overlap(edge, edge_box(q0, q1)) && edges_cross(p0, p1, q0, q1)) ++crossings;
    }
  }
  return crossings;
}

}  // namespace

BodySeparation body_separation(const std::vector<MassSpringBody>& bodies, std::array<double, 2> lower,
                               std::array<double, 2> upper, std::array<bool, 2> periodic) {
  BodySeparation s;
  s.min_rim_distance = std::numeric_limits<double>::infinity();
  s.min_wall_distance = std::numeric_limits<double>::infinity();
  const std::size_t n = bodies.size();
  std::vector<Box> box(n);
  double extent = 0.0;  // the largest box side
  for (std::size_t b = 0; b < n; ++b) {
    const MassSpringBody& body = bodies[b];
    for (int l = 0; l < body.n_surface; ++l)
      for (int d = 0; d < 2; ++d)
        if (!periodic[d])
          s.min_wall_distance = std::min({s.min_wall_distance, body.position[l][d] - lower[d], upper[d] - body.position[l][d]});
    box[b] = rim_box(body);
    extent = std::max({extent, box[b].high[0] - box[b].low[0], box[b].high[1] - box[b].low[1]});
    if (body.kind == BodyKind::mass_spring) s.n_self_crossings += rim_self_crossings(body);
  }
  if (n < 2) return s;
  // The shift that brings body b next to body a: the minimum image of their boxes' centres (a
  // body's points stay within one period of each other, so one image per pair is enough).
  const auto shift_of = [&](std::size_t a, std::size_t b) {
    Vec shift{0.0, 0.0};
    for (int d = 0; d < 2; ++d)
      if (periodic[d]) {
        const double length = upper[d] - lower[d];
        const double offset = 0.5 * (box[b].low[d] + box[b].high[d] - box[a].low[d] - box[a].high[d]);
        shift[d] = -length * std::round(offset / length);
      }
    return shift;
  };
  const auto shifted = [](const Box& b, const Vec& shift) {
    return Box{{b.low[0] + shift[0], b.low[1] + shift[1]}, {b.high[0] + shift[0], b.high[1] + shift[1]}};
  };
  // Broad phase: the boxes' centres hashed into cells of side at least 2 * extent, so that two boxes less
  // than `extent` apart sit in the same or neighbouring cells; the pairs found are sorted, so that
  // the result does not depend on the hashing order.
  const double cell = std::max(2.0 * extent, std::numeric_limits<double>::min());
  const auto box_centre = [&](int b) {
    return Vec{0.5 * (box[b].low[0] + box[b].high[0]), 0.5 * (box[b].low[1] + box[b].high[1])};
  };
  std::vector<std::pair<long, int>> hashed;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for_each_near_pair(
      static_cast<int>(n), box_centre, [](int) { return true; }, lower, {upper[0] - lower[0], upper[1] - lower[1]}, periodic, cell, hashed,
      [&](int a, int b) { pairs.emplace_back(a, b); });
  std::sort(pairs.begin(), pairs.end());  // each pair once; in index order
  // The smallest rim distance of one pair, over the points of each within `bound` of the other's box.
  std::vector<Vec> near_a, near_b;
  const auto pair_distance = [&](std::size_t a, std::size_t b, const Vec& shift, double bound) {
    const Box box_b = shifted(box[b], shift);
    near_a.clear();
    near_b.clear();
    for (int l = 0; l < bodies[a].n_surface; ++l)
      if (box_distance(box_b, bodies[a].position[l]) <= bound) near_a.push_back(bodies[a].position[l]);
    for (int m = 0; m < bodies[b].n_surface; ++m) {
      const Vec q{bodies[b].position[m][0] + shift[0], bodies[b].position[m][1] + shift[1]};
      if (box_distance(box[a], q) <= bound) near_b.push_back(q);
    }
    double best = bound;
    for (const Vec& p : near_a)
      for (const Vec& q : near_b) best = std::min(best, std::hypot(q[0] - p[0], q[1] - p[1]));
    return best;
  };
  for (const auto& [a, b] : pairs) {
    const Vec shift = shift_of(a, b);
    const Box box_b = shifted(box[b], shift);
    if (box_gap(box[a], box_b) < s.min_rim_distance)
      s.min_rim_distance = std::min(s.min_rim_distance, pair_distance(a, b, shift, s.min_rim_distance));
    if (!boxes_overlap(box[a], box_b)) continue;
    // Interpenetration needs overlapping boxes: rim points of one inside the other's rim, and rim
    // edges that cross (without a vertex inside).
    const MassSpringBody& A = bodies[a];
    const MassSpringBody& B = bodies[b];
    for (int l = 0; l < A.n_surface; ++l) {
      const Vec p{A.position[l][0] - shift[0], A.position[l][1] - shift[1]};
      if (box_distance(box[b], p) == 0.0 && inside_rim(B, p)) ++s.n_points_inside_others;
    }
    for (int m = 0; m < B.n_surface; ++m) {
      const Vec q{B.position[m][0] + shift[0], B.position[m][1] + shift[1]};
      if (box_distance(box[a], q) == 0.0 && inside_rim(A, q)) ++s.n_points_inside_others;
    }
    for (int l = 0; l < A.n_surface; ++l) {
      const Vec& p0 = A.position[l];
      const Vec& p1 = A.position[(l + 1) % A.n_surface];
      const Box edge = edge_box(p0, p1);
      if (!boxes_overlap(edge, box_b)) continue;
      for (int m = 0; m < B.n_surface; ++m) {
        const Vec q0{B.position[m][0] + shift[0], B.position[m][1] + shift[1]};
        const Vec q1{B.position[(m + 1) % B.n_surface][0] + shift[0], B.position[(m + 1) % B.n_surface][1] + shift[1]};
        if (edges_cross(p0, p1, q0, q1)) ++s.n_edge_crossings;
      }
    }
  }
  // A pass with cells of side c visits every pair whose boxes' centres are less than c apart in each
  // direction, so every pair of rims less than c - extent apart. No pair found within that reach (a
  // sparse scene): the centres hashed again into cells twice as large, until a pair within reach is
  // found or one cell holds the box (every pair), each pair pruned by its boxes' gap.
  const double span = std::max(upper[0] - lower[0], upper[1] - lower[1]);
  for (double c = cell; !(s.min_rim_distance <= c - extent) && c < span;) {
    c *= 2.0;
    for_each_near_pair(
        static_cast<int>(n), box_centre, [](int) { return true; }, lower, {upper[0] - lower[0], upper[1] - lower[1]}, periodic, c, hashed,
        [&](int a, int b) {
          const Vec shift = shift_of(a, b);
          if (box_gap(box[a], shifted(box[b], shift)) < s.min_rim_distance)
            s.min_rim_distance = std::min(s.min_rim_distance, pair_distance(a, b, shift, s.min_rim_distance));
        });
  }
  return s;
}

}  // namespace ibms
