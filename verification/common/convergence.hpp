// Convergence bookkeeping shared by verification programs: pairwise observed orders, the
// least-squares log-log slope over the finest three levels (DESIGN.md §6), and a printed table.
// When the environment variable IBMS_RESULTS_DIR is set (ctest sets it for every test), each
// table is also appended to $IBMS_RESULTS_DIR/convergence.csv (title,N,h,error,order) for the
// report (reports/README.md).
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
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

// Appends one table as CSV rows "title",N,h,error,order (order empty on the coarsest level) to
// $IBMS_RESULTS_DIR/convergence.csv; does nothing if the variable is unset. The CSV title is
// "<program>: <title>", with " (table k)" added when a program prints the same title k > 1 times
// (e.g. the steady and the unsteady study of the manufactured solution), so tables stay distinct. The block goes out in
// one append-mode write, so tests running in parallel do not interleave rows; the header line is
// written by whoever creates the file. Failures to write are reported on stderr, never thrown.
inline void append_convergence_csv(const std::string& title, const std::vector<int>& n,
                                   const std::vector<double>& h, const std::vector<double>& e) {
  const char* dir = std::getenv("IBMS_RESULTS_DIR");
  if (dir == nullptr || *dir == '\0') return;
  const std::string path = std::string(dir) + "/convergence.csv";
  static std::map<std::string, int> printed;  // per program: how often each title was written
  std::string full = title;
#ifdef __GLIBC__
  full = std::string(program_invocation_short_name) + ": " + title;
#endif
  if (const int k = ++printed[title]; k > 1) full += " (table " + std::to_string(k) + ")";
  std::string quoted = "\"";
  for (char c : full) quoted += (c == '"') ? std::string("\"\"") : std::string(1, c);
  quoted += "\"";
  const std::vector<double> orders = pairwise_orders(h, e);
  std::string block;
  for (std::size_t k = 0; k < e.size() && k < n.size() && k < h.size(); ++k) {
    char line[160];
    if (k == 0) std::snprintf(line, sizeof line, ",%d,%.17g,%.17g,\n", n[k], h[k], e[k]);
    else std::snprintf(line, sizeof line, ",%d,%.17g,%.17g,%.6g\n", n[k], h[k], e[k], orders[k - 1]);
    block += quoted + line;
  }
  int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_EXCL, 0644);
  if (fd >= 0) block = "title,N,h,error,order\n" + block;
  else fd = ::open(path.c_str(), O_WRONLY | O_APPEND);
  if (fd < 0) {
    std::fprintf(stderr, "convergence_table: cannot append to %s\n", path.c_str());
    return;
  }
  if (::write(fd, block.data(), block.size()) != static_cast<ssize_t>(block.size()))
    std::fprintf(stderr, "convergence_table: short write to %s\n", path.c_str());
  ::close(fd);
}

// Table "N  error  order" for the log (ctest -V shows it); also appended as CSV when
// IBMS_RESULTS_DIR is set (append_convergence_csv).
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
  append_convergence_csv(title, n, h, e);
  return out.str();
}

}  // namespace ibms::verification
