// Pairs of nearby objects without an all-pairs loop: each object's centre is hashed into the cells
// of a grid that tiles the box (cells of side at least `cell`, a periodic coordinate wrapped first),
// and every pair in the same or neighbouring cells is visited once. Two centres less than `cell`
// apart in each direction are always visited; farther ones may be. The pairs' order follows the
// sorted cell keys, so it does not depend on how the objects were listed beyond their indices.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace ibms {

// centre(b) -> std::array<double, 2>; include(b): whether object b takes part; visit(a, b) with
// a < b. hashed: storage kept by the caller (no allocation once it has grown).
template <class Centre, class Include, class Visit>
void for_each_near_pair(int n, Centre centre, Include include, std::array<double, 2> origin,
                        std::array<double, 2> length, std::array<bool, 2> periodic, double cell,
                        std::vector<std::pair<long, int>>& hashed, Visit visit) {
  std::array<long, 2> cells{1, 1};
  for (int d = 0; d < 2; ++d)  // clamped as a double: a tiny cell cannot overflow the cast
    cells[d] = static_cast<long>(std::clamp(std::floor(length[d] / cell), 1.0, 1048576.0));
  const auto index = [&](const std::array<double, 2>& x, int d) {
    double s = x[d] - origin[d];
    if (periodic[d]) s -= length[d] * std::floor(s / length[d]);
    const double k = std::floor(s * cells[d] / length[d]);  // clamped as a double (NaN: cell 0)
    return k >= 0.0 ? static_cast<long>(std::min(k, static_cast<double>(cells[d] - 1))) : 0L;
  };
  hashed.clear();
  for (int b = 0; b < n; ++b)
    if (include(b)) {
      const std::array<double, 2> x = centre(b);
      hashed.emplace_back(index(x, 0) + cells[0] * index(x, 1), b);
    }
  std::sort(hashed.begin(), hashed.end());
  for (const auto& [key_a, a] : hashed) {
    const long ia = key_a % cells[0], ja = key_a / cells[0];
    // Neighbouring cells, each once (a periodic direction of fewer than three cells wraps onto itself).
    std::array<long, 9> keys{};
    int n_keys = 0;
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di) {
        long i = ia + di, j = ja + dj;
        if (periodic[0]) i = ((i % cells[0]) + cells[0]) % cells[0];
        if (periodic[1]) j = ((j % cells[1]) + cells[1]) % cells[1];
        if (i < 0 || i >= cells[0] || j < 0 || j >= cells[1]) continue;
        const long key = i + cells[0] * j;
        if (std::find(keys.begin(), keys.begin() + n_keys, key) == keys.begin() + n_keys) keys[n_keys++] = key;
      }
    for (int k = 0; k < n_keys; ++k) {
      auto it = std::lower_bound(hashed.begin(), hashed.end(), std::pair<long, int>{keys[k], -1});
      for (; it != hashed.end() && it->first == keys[k]; ++it)
        if (it->second > a) visit(a, it->second);
    }
  }
}

}  // namespace ibms
