// CDS pair search, docs/method.md §1.9: body-box broad phase (walled boxes) and cell list with bins
// >= 2 r_max (periodic boxes). The brute-force reference is a test oracle
// (verification/oracles/brute_force_pair_search.hpp).
#include "contact/cds_pair_search.hpp"

#include "core/cell_hash.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

ContactSpheres gather_contact_spheres(const ContactModel& model,
                                      const std::vector<MassSpringBody>& bodies) {
  ContactSpheres spheres;
  gather_contact_spheres(model, bodies, spheres);
  return spheres;
}

void gather_contact_spheres(const ContactModel& model, const std::vector<MassSpringBody>& bodies,
                            ContactSpheres& spheres, const BodySet& members) {
  spheres.centre.clear();
  spheres.radius.clear();
  spheres.body.clear();
  spheres.point.clear();
  for (std::size_t i = 0; i < members.count(bodies.size()); ++i) {
    const int b = static_cast<int>(members.at(i));
    const double radius = model.cds_radius_of(bodies[b]);
    for (int k = 0; k < model.cds_points(bodies[b]); ++k) {  // surface points (and the centre with centre_point)
      spheres.centre.push_back(bodies[b].position[k]);
      spheres.radius.push_back(radius);
      spheres.body.push_back(b);
      spheres.point.push_back(k);
    }
  }
}

std::array<double, 2> separation(const std::array<double, 2>& from, const std::array<double, 2>& to,
                                 const WallBox& box) {
  std::array<double, 2> d{to[0] - from[0], to[1] - from[1]};
  for (int c = 0; c < 2; ++c)
    if (box.periodic[c]) d[c] -= box.length[c] * std::round(d[c] / box.length[c]);
  return d;
}

namespace {

// Examines one candidate pair s < t and records it if the spheres of different bodies touch.
void check_pair(const ContactSpheres& spheres, const WallBox& box, int s, int t,
                PairSearchResult& result) {
  ++result.n_pair_checks;
  if (spheres.body[s] == spheres.body[t]) return;  // CDS of one body never act on each other
  const std::array<double, 2> d = separation(spheres.centre[s], spheres.centre[t], box);
  const double contact_distance = spheres.radius[s] + spheres.radius[t];
  if (d[0]*d[0] + d[1]*d[1] < contact_distance*contact_distance) result.pairs.push_back({s, t});
}

void sort_pairs(PairSearchResult& result) {
  std::sort(result.pairs.begin(), result.pairs.end(), [](const SpherePair& a, const SpherePair& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  });
}

// Bins along one direction: the period if periodic, else the span of the centres; width >= 2 r_max.
struct BinAxis {
  double lower = 0.0, width = 1.0;
  int n_bins = 1;
  bool periodic = false;

  int index(double x) const {
    const int i = static_cast<int>(std::floor((x - lower) / width));
    if (periodic) return ((i % n_bins) + n_bins) % n_bins;
    return std::clamp(i, 0, n_bins - 1);  // nothing lies outside the span; guards round-off
  }
  // Distinct bins i-1, i, i+1 (wrapped if periodic) into out[]; fewer when n_bins < 3 or at an
  // end. Returns their number. No allocation: this runs for every sphere of every sub-step.
  int neighbours(int i, int out[3]) const {
    int count = 0;
    for (int d = -1; d <= 1; ++d) {
      int j = i + d;
      if (periodic) j = ((j % n_bins) + n_bins) % n_bins;
      else if (j < 0 || j >= n_bins) continue;
      if (std::find(out, out + count, j) == out + count) out[count++] = j;
    }
    return count;
  }
};

// max_bins caps the bins per axis (wider bins stay correct, >= bin_min): a few tiny spheres spread
// over a large box would otherwise make a mostly empty grid that costs more than it saves.
BinAxis make_axis(const ContactSpheres& spheres, const WallBox& box, int c, double bin_min, int max_bins) {
  BinAxis axis;
  axis.periodic = box.periodic[c];
  double upper;
  if (axis.periodic) {
    axis.lower = box.origin[c];
    upper = box.origin[c] + box.length[c];
  } else {
    axis.lower = upper = spheres.centre[0][c];
    for (const auto& x : spheres.centre) {
      axis.lower = std::min(axis.lower, x[c]);
      upper = std::max(upper, x[c]);
    }
  }
  const double span = upper - axis.lower;
  // Clamp in floating point first: span / bin_min can exceed INT_MAX for tiny spheres.
  axis.n_bins = static_cast<int>(std::clamp(std::floor(span / bin_min), 1.0, static_cast<double>(max_bins)));
  axis.width = span > 0.0 ? span / axis.n_bins : 1.0;  // >= bin_min by the floor above
  return axis;
}

}  // namespace

PairSearchResult find_touching_pairs_cell_list(const ContactSpheres& spheres, const WallBox& box) {
  PairSearchResult result;
  const int n = spheres.n_spheres();
  if (n < 2) return result;
  // Touching spheres are closer than 2 r_max, so they lie in the same or adjacent bins.
  const double bin_min = 2.0 * *std::max_element(spheres.radius.begin(), spheres.radius.end());
  const int max_bins = 4 * static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))) + 1;
  const BinAxis axis_x = make_axis(spheres, box, 0, bin_min, max_bins);
  const BinAxis axis_y = make_axis(spheres, box, 1, bin_min, max_bins);
  // Spheres sorted by bin (counting sort): bin b holds order[start[b] .. start[b + 1]). The work
  // arrays are kept between calls (one search per solid sub-step).
  thread_local std::vector<int> bin_of, start, cursor, order;
  const int n_bins = axis_x.n_bins * axis_y.n_bins;
  bin_of.resize(n);
  order.resize(n);
  start.assign(n_bins + 1, 0);
  for (int s = 0; s < n; ++s) {
    bin_of[s] = axis_x.index(spheres.centre[s][0]) + axis_x.n_bins * axis_y.index(spheres.centre[s][1]);
    ++start[bin_of[s] + 1];
  }
  for (int b = 0; b < n_bins; ++b) start[b + 1] += start[b];
  cursor.assign(start.begin(), start.end() - 1);
  for (int s = 0; s < n; ++s) order[cursor[bin_of[s]]++] = s;
  for (int s = 0; s < n; ++s) {
    const int i = bin_of[s] % axis_x.n_bins, j = bin_of[s] / axis_x.n_bins;
    int near_x[3], near_y[3];
    const int n_near_x = axis_x.neighbours(i, near_x), n_near_y = axis_y.neighbours(j, near_y);
    // Each unordered pair once: from its lower index s, over distinct neighbour bins.
    for (int b_y = 0; b_y < n_near_y; ++b_y)
      for (int b_x = 0; b_x < n_near_x; ++b_x) {
        const int bin = near_x[b_x] + axis_x.n_bins * near_y[b_y];
        for (int k = start[bin]; k < start[bin + 1]; ++k)
          if (order[k] > s) check_pair(spheres, box, s, order[k], result);
      }
  }
  sort_pairs(result);
  return result;
}

PairSearchResult find_touching_pairs_body_bounds(const ContactSpheres& spheres, const WallBox& box) {
  PairSearchResult result;
  find_touching_pairs_body_bounds(spheres, box, result);
  return result;
}

void find_touching_pairs_body_bounds(const ContactSpheres& spheres, const WallBox& box, PairSearchResult& result) {
  if (box.periodic[0] || box.periodic[1]) {
    result = find_touching_pairs_cell_list(spheres, box);
    return;
  }
  result.pairs.clear();
  result.n_pair_checks = 0;
  const int n = spheres.n_spheres();
  if (n < 2) return;
  // The spheres in runs of one body (gather_contact_spheres lists each body's spheres together):
  // run b holds spheres start[b] .. start[b + 1]. Runs, not body indices, so that a group of k
  // bodies costs O(k) whatever the scene's number of bodies. A body split over several runs still
  // gives the right pairs (check_pair rejects spheres of one body by their body index), at the cost
  // of the tests between its runs.
  thread_local std::vector<int> start;
  thread_local std::vector<std::array<double, 4>> bounds;  // x_min, x_max, y_min, y_max of the spheres
  start.clear();
  for (int s = 0; s < n; ++s)
    if (s == 0 || spheres.body[s] != spheres.body[s - 1]) start.push_back(s);
  const int n_bodies = static_cast<int>(start.size());
  start.push_back(n);
  bounds.assign(n_bodies, {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL});
  for (int b = 0; b < n_bodies; ++b)
    for (int s = start[b]; s < start[b + 1]; ++s) {
      auto& bb = bounds[b];
      const auto& x = spheres.centre[s];
      const double r = spheres.radius[s];
      bb = {std::min(bb[0], x[0] - r), std::max(bb[1], x[0] + r), std::min(bb[2], x[1] - r), std::max(bb[3], x[1] + r)};
    }
  // Broad phase without an all-pairs loop: the boxes' centres hashed into cells of the largest box
  // side, so that two overlapping boxes (centres less than the mean of their sides apart in each
  // direction) are always visited.
  double side = 0.0;
  std::array<double, 2> low{HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL};
  for (int b = 0; b < n_bodies; ++b) {
    const auto& bb = bounds[b];
    side = std::max({side, bb[1] - bb[0], bb[3] - bb[2]});
    low = {std::min(low[0], bb[0]), std::min(low[1], bb[2])};
    high = {std::max(high[0], bb[1]), std::max(high[1], bb[3])};
  }
  thread_local std::vector<std::pair<long, int>> hashed;
  thread_local std::vector<int> near_a, near_b;
  const auto visit = [&](int a, int b) {
    ++result.n_pair_checks;  // the broad-phase test of the two bodies' boxes
    const auto& p = bounds[a];
    const auto& q = bounds[b];
    // Touching spheres lie in both boxes: disjoint boxes have no touching pair (closed intervals
    // overlap test; a pair at exactly r_i + r_j does not touch either way).
    if (p[1] < q[0] || q[1] < p[0] || p[3] < q[2] || q[3] < p[2]) return;
    // Narrow phase: two touching spheres' own boxes overlap, so each meets the boxes' common part;
    // only the spheres of each body that do are paired.
    const std::array<double, 4> common{std::max(p[0], q[0]), std::min(p[1], q[1]), std::max(p[2], q[2]),
                                       std::min(p[3], q[3])};
    const auto collect = [&](int body, std::vector<int>& out) {
      out.clear();
      for (int t = start[body]; t < start[body + 1]; ++t) {
        const auto& x = spheres.centre[t];
        const double r = spheres.radius[t];
        if (x[0] + r >= common[0] && x[0] - r <= common[1] && x[1] + r >= common[2] && x[1] - r <= common[3])
          out.push_back(t);
      }
    };
    collect(a, near_a);
    collect(b, near_b);
    for (const int k : near_a)
      for (const int m : near_b) check_pair(spheres, box, std::min(k, m), std::max(k, m), result);
  };
  if (side > 0.0)
    for_each_near_pair(
        n_bodies, [&](int b) { return std::array<double, 2>{0.5 * (bounds[b][0] + bounds[b][1]),
                                                            0.5 * (bounds[b][2] + bounds[b][3])}; },
        [](int) { return true; }, low, {high[0] - low[0], high[1] - low[1]}, {false, false},
        side, hashed, visit);
  sort_pairs(result);
}

void keep_touching_pairs(const ContactSpheres& spheres, const WallBox& box, const std::vector<SpherePair>& candidates,
                         PairSearchResult& out) {
  out.pairs.clear();
  out.n_pair_checks = 0;
  for (const SpherePair& pair : candidates) check_pair(spheres, box, pair.first, pair.second, out);
}

}  // namespace ibms
