// Convergence bookkeeping shared by verification programs: pairwise observed orders, the
// least-squares log-log slope over the finest three levels (DESIGN.md §6), and a printed table.
#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace ibms::verification {

// Observed order between consecutive levels: log(e_k/e_{k+1}) / log(h_k/h_{k+1}).
inline std::vector<double> pairwise_orders(const std::vector<double>& h, const std::vector<double>& e) {
  std::vector<double> orders;
  for (std::size_t k = 0; k + 1 < e.size(); ++k)
    orders.push_back(std::log(e[k] / e[k + 1]) / std::log(h[k] / h[k + 1]));
  return orders;
}

// Least-squares slope of log e against log h over the last three (finest) levels.
inline double finest_three_slope(const std::vector<double>& h, const std::vector<double>& e) {
  const std::size_t n = h.size(), first = n >= 3 ? n - 3 : 0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t k = first; k < n; ++k) {
    const double x = std::log(h[k]), y = std::log(e[k]);
    sx += x; sy += y; sxx += x * x; sxy += x * y; m += 1;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

// Table "N  error  order" for the log (ctest -V shows it).
inline std::string convergence_table(const std::string& title, const std::vector<int>& n,
                                     const std::vector<double>& h, const std::vector<double>& e) {
  std::ostringstream out;
  const std::vector<double> orders = pairwise_orders(h, e);
  out << title << "\n    N        error       order\n";
  for (std::size_t k = 0; k < e.size(); ++k) {
    char line[96];
    if (k == 0) std::snprintf(line, sizeof line, "%5d  %12.4e           -\n", n[k], e[k]);
    else std::snprintf(line, sizeof line, "%5d  %12.4e  %10.3f\n", n[k], e[k], orders[k - 1]);
    out << line;
  }
  char fit[64];
  std::snprintf(fit, sizeof fit, "  slope over finest three levels: %.3f", finest_three_slope(h, e));
  out << fit;
  return out.str();
}

}  // namespace ibms::verification
