// CDS pair search, METHOD.md §1.9: cell list with bins >= 2 r_max, and brute force for reference.
#include "contact/cds_pair_search.hpp"

#include <algorithm>
#include <cmath>

namespace ibms {

ContactSpheres gather_contact_spheres(const ContactModel& model,
                                      const std::vector<MassSpringBody>& bodies) {
  ContactSpheres spheres;
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
    const double radius = model.cds_radius_of(bodies[b]);
    for (int k = 0; k < bodies[b].n_surface; ++k) {  // surface points only; the centre has no CDS
      spheres.centre.push_back(bodies[b].position[k]);
      spheres.radius.push_back(radius);
      spheres.body.push_back(b);
      spheres.point.push_back(k);
    }
  }
  return spheres;
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
  // Distinct bins i-1, i, i+1 (wrapped if periodic); fewer when n_bins < 3 or at an end.
  std::vector<int> neighbours(int i) const {
    std::vector<int> result;
    for (int d = -1; d <= 1; ++d) {
      int j = i + d;
      if (periodic) j = ((j % n_bins) + n_bins) % n_bins;
      else if (j < 0 || j >= n_bins) continue;
      if (std::find(result.begin(), result.end(), j) == result.end()) result.push_back(j);
    }
    return result;
  }
};

BinAxis make_axis(const ContactSpheres& spheres, const WallBox& box, int c, double bin_min) {
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
  axis.n_bins = std::max(1, static_cast<int>(std::floor(span / bin_min)));
  axis.width = span > 0.0 ? span / axis.n_bins : 1.0;  // >= bin_min by the floor above
  return axis;
}

}  // namespace

PairSearchResult find_touching_pairs_brute_force(const ContactSpheres& spheres, const WallBox& box) {
  PairSearchResult result;
  for (int s = 0; s < spheres.n_spheres(); ++s)
    for (int t = s + 1; t < spheres.n_spheres(); ++t) check_pair(spheres, box, s, t, result);
  sort_pairs(result);
  return result;
}

PairSearchResult find_touching_pairs_cell_list(const ContactSpheres& spheres, const WallBox& box) {
  PairSearchResult result;
  if (spheres.n_spheres() < 2) return result;
  // Touching spheres are closer than 2 r_max, so they lie in the same or adjacent bins.
  const double bin_min = 2.0 * *std::max_element(spheres.radius.begin(), spheres.radius.end());
  const BinAxis axis_x = make_axis(spheres, box, 0, bin_min);
  const BinAxis axis_y = make_axis(spheres, box, 1, bin_min);
  std::vector<std::vector<int>> members(static_cast<std::size_t>(axis_x.n_bins) * axis_y.n_bins);
  std::vector<int> bin_of(spheres.n_spheres());
  for (int s = 0; s < spheres.n_spheres(); ++s) {
    bin_of[s] = axis_x.index(spheres.centre[s][0]) + axis_x.n_bins * axis_y.index(spheres.centre[s][1]);
    members[bin_of[s]].push_back(s);
  }
  for (int s = 0; s < spheres.n_spheres(); ++s) {
    const int i = bin_of[s] % axis_x.n_bins, j = bin_of[s] / axis_x.n_bins;
    // Each unordered pair once: from its lower index s, over distinct neighbour bins.
    for (int jn : axis_y.neighbours(j))
      for (int in : axis_x.neighbours(i))
        for (int t : members[in + axis_x.n_bins * jn])
          if (t > s) check_pair(spheres, box, s, t, result);
  }
  sort_pairs(result);
  return result;
}

}  // namespace ibms
