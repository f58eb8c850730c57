// Body histories (body_series.hpp).
#include "metrics/body_series.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "metrics/csv_reader.hpp"

namespace ibms {

SeriesTable read_series_csv(const std::string& path) {
  CsvTable t = read_csv(path);
  SeriesTable table;
  for (std::size_t c = 0; c < t.names.size(); ++c) table[t.names[c]] = std::move(t.columns[c]);
  return table;
}

const std::vector<double>& series_column(const SeriesTable& table, const std::string& name, const std::string& path) {
  const auto it = table.find(name);
  if (it == table.end()) throw InputError(path + ": no column '" + name + "'");
  return it->second;
}

double first_crossing_below(const std::vector<double>& time, const std::vector<double>& values, double level) {
  for (std::size_t k = 1; k < values.size() && k < time.size(); ++k)
    if (values[k] <= level && values[k - 1] > level) {
      const double w = (values[k - 1] - level) / (values[k - 1] - values[k]);
      return time[k - 1] + w * (time[k] - time[k - 1]);
    }
  return NAN;
}

double path_length(const std::vector<double>& time, const std::vector<double>& x, const std::vector<double>& y,
                   double t0, double t1) {
  double length = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k)
    if (time[k - 1] >= t0 && time[k] <= t1) length += std::hypot(x[k] - x[k - 1], y[k] - y[k - 1]);
  return length;
}

double max_settling_speed(const std::vector<double>& velocity_y, std::size_t* index) {
  std::size_t k_max = 0;
  for (std::size_t k = 0; k < velocity_y.size(); ++k)
    if (-velocity_y[k] > -velocity_y[k_max]) k_max = k;
  if (index != nullptr) *index = k_max;
  return velocity_y.empty() ? NAN : -velocity_y[k_max];
}

}  // namespace ibms
