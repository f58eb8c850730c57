// Convergence bookkeeping shared by verification programs: pairwise observed orders, the
// least-squares log-log slope over the finest three levels with its standard error (docs/design.md §6;
// metrics::observed_order, GSL's linear fit), and a printed table. When the environment variable
// IBMS_RESULTS_DIR is set (ctest sets it for every test), each table is also appended to
// $IBMS_RESULTS_DIR/convergence.csv (title,N,h,error,order,fit_order,fit_standard_error,
// formal_order,asserted_min,asserted_max,refined; the fit and the test's OrderClaim on the finest
// row) for the report (reports/README.md), which shows these figures and fits nothing.
#pragma once
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "metrics/grid_convergence.hpp"
#include "results_csv.hpp"

namespace ibms::verification {

// Observed order between consecutive levels: log(e_k/e_{k+1}) / log(h_k/h_{k+1}).
inline std::vector<double> pairwise_orders(const std::vector<double>& h, const std::vector<double>& e) {
  std::vector<double> orders;
  for (std::size_t k = 0; k + 1 < e.size(); ++k)
    orders.push_back(std::log(e[k] / e[k + 1]) / std::log(h[k] / h[k + 1]));
  return orders;
}

// Least-squares slope of log e against log h over the last three (finest) levels, and its
// standard error (NaN with two levels).
inline ObservedOrder finest_three_fit(const std::vector<double>& h, const std::vector<double>& e) {
  return observed_order(h, e, 3);
}
inline double finest_three_slope(const std::vector<double>& h, const std::vector<double>& e) {
  return finest_three_fit(h, e).order;
}

// With the order, the tests assert that the finest three errors lie on one line in log-log: the
// fit's standard error at most 0.1 (pairwise orders differing by more than ~0.35 fail it), so a
// slope averaged over a kink (not yet asymptotic, or a change of the leading error term) does not
// pass (every pairwise order > 0 alone would assert almost nothing).
// Measured (ctest -L convergence): at most 0.084 (Galilean invariance), 0.072
// (Taylor-Green), <= 0.033 for the others.
inline constexpr double max_order_standard_error = 0.1;
// A convergence claim's band is closed above: the fitted order at most this much above the formal
// one. An order half an order or more above the formal one means the finest grids are not in the
// asymptotic range (or errors of opposite sign cancel), so the claim "order p" could not be made
// from them; the test fails instead of passing silently.
inline constexpr double max_order_excess = 0.5;

// Appends one table as CSV rows "title",N,h,error,order (order empty on the coarsest level) to
// $IBMS_RESULTS_DIR/convergence.csv; does nothing if the variable is unset. The CSV title is
// "<program>: <title>", with " (table k)" added when a program prints the same title k > 1 times
// (e.g. the steady and the unsteady study of the manufactured solution), so tables stay distinct. The block goes out in
// one append-mode write, so tests running in parallel do not interleave rows; the header line is
// written by whoever creates the file. Failures to write are reported on stderr, never thrown.
// What a convergence test claims about its table, written beside the figures for the report: the
// formal order of the scheme, the band the test asserts the fitted order in (NaN: no order
// asserted) and whether the table refines the grid ("h") or the time step ("dt").
struct OrderClaim {
  double formal = NAN, asserted_min = NAN, asserted_max = NAN;
  const char* refined = "h";
};

inline void append_convergence_csv(const std::string& title, const std::vector<int>& n,
                                   const std::vector<double>& h, const std::vector<double>& e,
                                   const OrderClaim& claim = {}) {
  const std::string dir = results::environment("IBMS_RESULTS_DIR");
  if (dir.empty()) return;
  const std::string path = dir + "/convergence.csv";
  static std::map<std::string, int> printed;  // per program: how often each title was written
  std::string full = title;
#ifdef __GLIBC__
  full = std::string(program_invocation_short_name) + ": " + title;
#endif
  if (const int k = ++printed[title]; k > 1) full += " (table " + std::to_string(k) + ")";
  const std::string quoted = csv_text(full, /*always_quote=*/true);
  const std::vector<double> orders = pairwise_orders(h, e);
  const ObservedOrder fit = finest_three_fit(h, e);
  const std::size_t n_rows = std::min({e.size(), n.size(), h.size()});
  std::vector<std::string> rows;
  for (std::size_t k = 0; k < n_rows; ++k) {
    char line[200];
    if (k == 0) std::snprintf(line, sizeof line, ",%d,%.17g,%.17g,", n[k], h[k], e[k]);
    else std::snprintf(line, sizeof line, ",%d,%.17g,%.17g,%.6g", n[k], h[k], e[k], orders[k - 1]);
    rows.push_back(quoted + line);
    if (k + 1 == n_rows) {
      std::snprintf(line, sizeof line, ",%.6g,%.3g,%s,%s,%s,%s", fit.order, fit.standard_error,
                    ibms::csv_number(claim.formal, true).c_str(), ibms::csv_number(claim.asserted_min, true).c_str(),
                    ibms::csv_number(claim.asserted_max, true).c_str(), claim.refined);
      rows.back() += line;
    } else {
      rows.back() += ",,,,,,";
    }
  }
  results::append_rows(
      path, "title,N,h,error,order,fit_order,fit_standard_error,formal_order,asserted_min,asserted_max,refined", rows,
      "convergence_table");
}

// Table "N  error  order" for the log (ctest -V shows it); also appended as CSV when
// IBMS_RESULTS_DIR is set (append_convergence_csv).
inline std::string convergence_table(const std::string& title, const std::vector<int>& n,
                                     const std::vector<double>& h, const std::vector<double>& e,
                                     const OrderClaim& claim = {}) {
  std::ostringstream out;
  const std::vector<double> orders = pairwise_orders(h, e);
  out << title << "\n    N        error       order\n";
  for (std::size_t k = 0; k < e.size(); ++k) {
    char line[96];
    if (k == 0) std::snprintf(line, sizeof line, "%5d  %12.4e           -\n", n[k], e[k]);
    else std::snprintf(line, sizeof line, "%5d  %12.4e  %10.3f\n", n[k], e[k], orders[k - 1]);
    out << line;
  }
  const ObservedOrder o = finest_three_fit(h, e);
  char fit[128];
  std::snprintf(fit, sizeof fit, "  least-squares order over the finest %d levels: %.3f +- %.3f (standard error)",
                o.points, o.order, o.standard_error);
  out << fit;
  append_convergence_csv(title, n, h, e, claim);
  return out.str();
}

}  // namespace ibms::verification
