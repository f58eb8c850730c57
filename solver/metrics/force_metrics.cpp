// Force-history figures (force_metrics.hpp).
#include "metrics/force_metrics.hpp"

#include <algorithm>
#include <stdexcept>

namespace ibms {

double rim_pressure(const std::array<double, 3>& d, const std::array<double, 3>& p) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    double weight = 1.0;
    for (int m = 0; m < 3; ++m)
      if (m != k) weight *= (0.0 - d[m]) / (d[k] - d[m]);
    sum += weight * p[k];
  }
  return sum;
}

double dfg_pressure_difference(const std::array<double, 6>& p) {
  return rim_pressure(dfg_probe_distance, {p[0], p[1], p[2]}) - rim_pressure(dfg_probe_distance, {p[3], p[4], p[5]});
}

PeriodicForces periodic_forces(const std::vector<double>& time, const std::vector<double>& drag,
                               const std::vector<double>& lift, const std::vector<double>& dp, double t_from,
                               double length, double speed) {
  PeriodicForces out;
  const std::size_t rows = time.size();
  double mean = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < rows; ++k)
    if (time[k] >= t_from) {
      mean += lift[k];
      ++n;
      out.drag_max = std::isnan(out.drag_max) ? drag[k] : std::max(out.drag_max, drag[k]);
      out.lift_max = std::isnan(out.lift_max) ? lift[k] : std::max(out.lift_max, lift[k]);
    }
  if (n < 10) throw std::runtime_error("fewer than 10 rows after t = " + std::to_string(t_from));
  mean /= n;
  // Upward crossings of lift - mean, linearly interpolated, with hysteresis: after a crossing the
  // next one counts only once the lift has gone below -band, a tenth of the amplitude, so that a
  // step-to-step jitter near zero (a coupling's corrections) does not count as a period.
  const double band = 0.1 * (out.lift_max - mean);
  std::vector<double> up;
  bool armed = false, first = true;
  for (std::size_t k = 1; k < rows; ++k) {
    if (time[k - 1] < t_from) continue;
    const double a = lift[k - 1] - mean, b = lift[k] - mean;
    if (first) armed = a < 0.0;  // the window may open below zero, inside the band
    first = false;
    if (a < -band) armed = true;
    if (armed && a < 0.0 && b >= 0.0) {
      up.push_back(time[k - 1] + (time[k] - time[k - 1]) * (-a) / (b - a));
      armed = false;
    }
  }
  if (up.size() < 3) throw std::runtime_error("fewer than two lift periods after t = " + std::to_string(t_from));
  out.periods = static_cast<int>(up.size()) - 1;
  const double period = (up.back() - up.front()) / out.periods;
  out.strouhal = length / (period * speed);
  if (dp.size() >= rows) {
    std::size_t last_max = 0;
    for (std::size_t k = 1; k + 1 < rows; ++k)
      if (time[k] >= t_from && lift[k] >= lift[k - 1] && lift[k] >= lift[k + 1] && time[k] + 0.5 * period <= time[rows - 1])
        last_max = k;
    if (last_max > 0) {
      const double target = time[last_max] + 0.5 * period;
      for (std::size_t k = last_max; k + 1 < rows; ++k)
        if (time[k + 1] >= target) {
          const double w = (target - time[k]) / (time[k + 1] - time[k]);
          out.pressure_difference_half_period = (1 - w) * dp[k] + w * dp[k + 1];
          break;
        }
    }
  }
  return out;
}

}  // namespace ibms
