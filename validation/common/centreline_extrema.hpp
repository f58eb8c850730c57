// The lid-driven cavity's centre-line extrema as compared with Botella & Peyret (1998) (issue 13):
// u_min on the vertical centre line, v_max and v_min on the horizontal one, each the vertex of the
// parabola through the discrete extremum and its two neighbours. One definition for the
// work-precision bench (bench_work_precision) and the accuracy test (test_cavity_accuracy).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ibms::validation {

// Vertex value of the parabola through the discrete extremum of f(s) and its neighbours (s increasing).
inline double parabola_extremum(const std::vector<double>& s, const std::vector<double>& f, bool minimum) {
  if (f.size() < 3 || s.size() != f.size()) throw std::invalid_argument("parabola_extremum: need >= 3 points");
  const auto it = minimum ? std::min_element(f.begin() + 1, f.end() - 1) : std::max_element(f.begin() + 1, f.end() - 1);
  const std::size_t k = static_cast<std::size_t>(it - f.begin());
  // Newton form f = f0 + d01 (x - x0) + d012 (x - x0)(x - x1); the vertex where f' = 0.
  const double d01 = (f[k] - f[k - 1]) / (s[k] - s[k - 1]), d12 = (f[k + 1] - f[k]) / (s[k + 1] - s[k]);
  const double d012 = (d12 - d01) / (s[k + 1] - s[k - 1]);
  if (d012 == 0.0) return f[k];
  const double xv = 0.5 * (s[k - 1] + s[k]) - d01 / (2.0 * d012);
  return f[k - 1] + d01 * (xv - s[k - 1]) + d012 * (xv - s[k - 1]) * (xv - s[k]);
}

// {u_min, v_max, v_min} of centre-line profiles u(y) on x = 1/2 and v(x) on y = 1/2.
inline std::array<double, 3> centreline_extrema(const std::vector<double>& y, const std::vector<double>& u,
                                                const std::vector<double>& x, const std::vector<double>& v) {
  return {parabola_extremum(y, u, true), parabola_extremum(x, v, false), parabola_extremum(x, v, true)};
}

// The published {u_min, v_max, v_min} of a case: reference/botella_peyret_extrema.csv
// (quantity,value,position; '#' comments).
inline std::array<double, 3> published_extrema(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::array<double, 3> values{NAN, NAN, NAN};
  const char* names[3] = {"u_min", "v_max", "v_min"};
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t comma = line.find(',');
    for (int q = 0; q < 3; ++q)
      if (line.substr(0, comma) == names[q]) values[q] = std::stod(line.substr(comma + 1));
  }
  for (double value : values)
    if (!std::isfinite(value)) throw std::runtime_error(path + ": u_min, v_max and v_min expected");
  return values;
}

// Largest |measured - published| over the three extrema.
inline double largest_extremum_error(const std::array<double, 3>& measured, const std::array<double, 3>& published) {
  double worst = 0.0;
  for (int q = 0; q < 3; ++q) worst = std::max(worst, std::abs(measured[q] - published[q]));
  return worst;
}

}  // namespace ibms::validation
