// Collatz-Wielandt upper bound of the spectral radius (Perron root) of a non-negative square matrix
// B, the bound behind the springs' sub-step (solid/stable_substep.cpp) and the contacts' inner step
// (contact/contact_subcycle_step_bound.cpp): rho(B) <= max_i (B x)_i / x_i for every x > 0, B
// reducible or not. Taken at x = 1 (iteration 0: Gershgorin's row sums) and at `iterations` power
// iterates, each divided by its largest entry, plus `floor` (which keeps x > 0 where B x has zero
// entries); the smallest of these bounds. 0 when B x vanishes. With min_improvement > 0 the
// iteration stops once an iterate lowers the bound by less than that fraction of it (the bounds of
// power iterates fall towards the Perron root; a bound stopped early is as rigorous, only less
// tight).
#pragma once
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace ibms {

// apply(x, y) sets y = B x; x and y are scratch, sized n here.
template <class Apply>
double collatz_wielandt_bound(std::size_t n, int iterations, double floor, std::vector<double>& x,
                              std::vector<double>& y, const Apply& apply, double min_improvement = 0.0) {
  x.assign(n, 1.0);
  y.resize(n);
  double best = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration <= iterations; ++iteration) {
    apply(x, y);
    double bound = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      bound = std::max(bound, y[i] / x[i]);
      largest = std::max(largest, y[i]);
    }
    const double before = best;
    best = std::min(best, bound);
    if (!(largest > 0.0)) return 0.0;
    if (before - best < min_improvement * best) break;
    for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / largest + floor;
  }
  return best;
}

}  // namespace ibms
