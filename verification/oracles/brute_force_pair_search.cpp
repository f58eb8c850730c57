#include "oracles/brute_force_pair_search.hpp"

#include <algorithm>

namespace ibms::oracles {

PairSearchResult find_touching_pairs_brute_force(const ContactSpheres& spheres, const WallBox& box) {
  PairSearchResult result;
  for (int s = 0; s < spheres.n_spheres(); ++s)
    for (int t = s + 1; t < spheres.n_spheres(); ++t) {
      ++result.n_pair_checks;
      if (spheres.body[s] == spheres.body[t]) continue;
      const std::array<double, 2> d = separation(spheres.centre[s], spheres.centre[t], box);
      const double reach = spheres.radius[s] + spheres.radius[t];
      if (d[0] * d[0] + d[1] * d[1] < reach * reach) result.pairs.push_back({s, t});
    }
  std::sort(result.pairs.begin(), result.pairs.end(), [](const SpherePair& a, const SpherePair& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  });
  return result;
}

}  // namespace ibms::oracles
