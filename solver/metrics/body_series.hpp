// Body histories: the series CSV `ibms run` writes beside its HDF5 output (<stem>_bodies.csv) and
// the figures the validation checks and `ibms compare` take from them, one definition each.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace ibms {

// Columns by lower-case name without the " [units]" suffix, e.g. "time", "body_000/velocity_y".
using SeriesTable = std::map<std::string, std::vector<double>>;

// Through read_csv (csv_reader.hpp): a non-numeric cell is an InputError naming file, line, column.
SeriesTable read_series_csv(const std::string& path);
// The column `name`; InputError naming `path` and the column when it is missing.
const std::vector<double>& series_column(const SeriesTable& table, const std::string& name, const std::string& path);

// First time at which `values` falls to `level` or below, linearly interpolated; NaN if never.
double first_crossing_below(const std::vector<double>& time, const std::vector<double>& values, double level);

// Path length of a point over [t0, t1]: the sum of the chords |x_k - x_{k-1}| between consecutive
// output times that both lie in the window (t_{k-1} >= t0 and t_k <= t1, compared exactly). The
// one definition of the body cavities' "mean path length" (check and `ibms compare`): it needs only
// positions, which every code writes; measured against the integral of the centre-of-mass speed
// on ibms's 100^2 runs (output every 0.02) it differs by < 1.1 % (docs/compare.md).
double path_length(const std::vector<double>& time, const std::vector<double>& x, const std::vector<double>& y,
                   double t0, double t1);

// Largest settling speed max_k(-v_k) of a vertical velocity series (negative downwards), and the
// index where it occurs.
double max_settling_speed(const std::vector<double>& velocity_y, std::size_t* index = nullptr);

}  // namespace ibms
