// Convergence figures (grid_convergence.hpp).
#include "metrics/grid_convergence.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ibms {

ObservedOrder observed_order(const std::vector<double>& h, const std::vector<double>& e, int levels) {
  if (h.size() != e.size() || h.size() < 2) throw std::invalid_argument("observed_order: need >= 2 (h, error) pairs");
  const std::size_t n = levels <= 0 ? h.size() : std::min<std::size_t>(h.size(), static_cast<std::size_t>(levels));
  if (n < 2) throw std::invalid_argument("observed_order: need >= 2 levels");
  std::vector<double> x, y;
  for (std::size_t k = h.size() - n; k < h.size(); ++k) {
    if (!(h[k] > 0.0) || !(e[k] > 0.0)) throw std::invalid_argument("observed_order: h and error must be positive");
    x.push_back(std::log(h[k]));
    y.push_back(std::log(e[k]));
  }
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  ObservedOrder o;
  o.order = c1;
  o.points = static_cast<int>(n);
  // GSL scales the covariance by sumsq / (n - 2): meaningless with two points.
  o.standard_error = n >= 3 ? std::sqrt(cov11) : NAN;
  return o;
}

GridConvergence grid_convergence(double h_fine, double h_medium, double h_coarse, double f_fine, double f_medium,
                                 double f_coarse, double formal_order) {
  GridConvergence g;
  const double r21 = h_medium / h_fine, r32 = h_coarse / h_medium;
  const double e21 = f_medium - f_fine, e32 = f_coarse - f_medium;
  g.monotone = e21 != 0.0 && e32 / e21 > 0.0;
  if (!g.monotone) return g;  // oscillatory or converged to round-off: no order
  // f = f* + C h^p gives e32 / e21 = r21^p (r32^p - 1) / (r21^p - 1), which grows with p from
  // ln r32 / ln r21 at p -> 0: a smaller ratio (the differences not shrinking enough, or growing)
  // fits no positive order.
  g.converging = e32 / e21 > std::log(r32) / std::log(r21);
  if (!g.converging) return g;
  double p = std::log(e32 / e21) / std::log(r21);
  for (int iteration = 0; iteration < 200; ++iteration) {  // eq. 3 with s = 1
    const double q = std::log((std::pow(r21, p) - 1.0) / (std::pow(r32, p) - 1.0));
    const double next = std::abs(std::log(e32 / e21) + q) / std::log(r21);
    const bool done = std::abs(next - p) < 1e-12;
    p = next;
    if (done) break;
  }
  const double rp = std::pow(r21, p);
  g.order = p;
  g.extrapolated = (rp * f_fine - f_medium) / (rp - 1.0);
  // Roache's GCI: the observed order with F_s = 1.25 where it is near the formal one (or none is
  // stated), else the order bounded by the formal one with F_s = 3 (Oberkampf & Roy 2010).
  const bool near_formal = !std::isfinite(formal_order) || std::abs(p - formal_order) <= 0.1 * formal_order;
  g.safety_factor = near_formal ? 1.25 : 3.0;
  g.gci_order = near_formal ? p : std::min(std::max(0.5, p), formal_order);
  g.gci_fine = g.safety_factor * std::abs(e21 / f_fine) / (std::pow(r21, g.gci_order) - 1.0);
  return g;
}

}  // namespace ibms
