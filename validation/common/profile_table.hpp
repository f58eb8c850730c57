// Reading the CSV tables of validation cases (ibms profiles and published references: '#'
// comment lines, one header line, numeric columns; an optional non-numeric flag column) and
// interpolating a profile at given abscissae by 4-point Lagrange interpolation (O(h^4)).
#pragma once
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ibms::validation {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;  // numeric columns
  std::vector<std::string> flags;            // third column text if present ("" when empty)
};

inline Table read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  Table t;
  std::string line;
  bool have_header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    if (!have_header) {
      t.header = cells;
      have_header = true;
      t.columns.resize(std::min<std::size_t>(cells.size(), 2));
      continue;
    }
    for (std::size_t c = 0; c < t.columns.size(); ++c) t.columns[c].push_back(std::stod(cells.at(c)));
    t.flags.push_back(cells.size() > 2 ? cells[2] : "");
  }
  if (t.columns.size() < 2 || t.columns[0].empty()) throw std::runtime_error(path + ": no data rows");
  return t;
}

// 4-point Lagrange interpolation of (x, f) at xq; x strictly increasing.
inline double interpolate(const std::vector<double>& x, const std::vector<double>& f, double xq) {
  const std::size_t n = x.size();
  std::size_t k = std::upper_bound(x.begin(), x.end(), xq) - x.begin();  // x[k-1] <= xq < x[k]
  k = std::clamp<std::size_t>(k, 2, n - 2);
  const std::size_t first = k - 2;
  double result = 0;
  for (std::size_t a = first; a < first + 4; ++a) {
    double w = 1;
    for (std::size_t b = first; b < first + 4; ++b)
      if (b != a) w *= (xq - x[b]) / (x[a] - x[b]);
    result += w * f[a];
  }
  return result;
}

// Extremum of an interpolated profile, sampled finely (for grid-convergence scalars).
inline double profile_extremum(const std::vector<double>& x, const std::vector<double>& f, bool maximum) {
  double best = maximum ? -HUGE_VAL : HUGE_VAL;
  const int samples = 4000;
  for (int s = 0; s <= samples; ++s) {
    const double xq = x.front() + (x.back() - x.front()) * s / samples;
    const double v = interpolate(x, f, xq);
    best = maximum ? std::max(best, v) : std::min(best, v);
  }
  return best;
}

// Grid convergence index of Celik et al. (2008), constant refinement ratio r, safety factor 1.25.
struct GciResult {
  double observed_order = 0, extrapolated = 0, gci_fine = 0;  // gci as a fraction of |phi_fine|
  bool monotone = false;
};
inline GciResult grid_convergence_index(double phi_coarse, double phi_medium, double phi_fine, double r) {
  GciResult g;
  const double e32 = phi_coarse - phi_medium, e21 = phi_medium - phi_fine;
  g.monotone = e32 * e21 > 0;
  g.observed_order = std::abs(std::log(std::abs(e32 / e21))) / std::log(r);
  const double rp = std::pow(r, g.observed_order);
  g.extrapolated = (rp * phi_fine - phi_medium) / (rp - 1);
  g.gci_fine = 1.25 * std::abs(e21 / phi_fine) / (rp - 1);
  return g;
}

// The same for refinement ratios r21 = h_medium / h_fine and r32 = h_coarse / h_medium that differ:
// the observed order by the fixed-point iteration of Celik et al. (2008) eqs. (3a-c),
// p = |ln|e32/e21| + q(p)| / ln r21, q(p) = ln((r21^p - s) / (r32^p - s)), s = sign(e32/e21).
inline GciResult grid_convergence_index(double phi_coarse, double phi_medium, double phi_fine, double r21,
                                        double r32) {
  GciResult g;
  const double e32 = phi_coarse - phi_medium, e21 = phi_medium - phi_fine;
  g.monotone = e32 * e21 > 0;
  const double s = g.monotone ? 1.0 : -1.0;
  double p = std::abs(std::log(std::abs(e32 / e21))) / std::log(r21);
  for (int k = 0; k < 100; ++k) {
    const double q = std::log((std::pow(r21, p) - s) / (std::pow(r32, p) - s));
    p = std::abs(std::log(std::abs(e32 / e21)) + q) / std::log(r21);
  }
  g.observed_order = p;
  const double rp = std::pow(r21, p);
  g.extrapolated = (rp * phi_fine - phi_medium) / (rp - 1);
  g.gci_fine = 1.25 * std::abs(e21 / phi_fine) / (rp - 1);
  return g;
}

}  // namespace ibms::validation
