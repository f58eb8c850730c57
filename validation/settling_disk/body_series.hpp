// Reading the body series CSV that `ibms run` writes beside its HDF5 output (<stem>_bodies.csv:
// '#' comment lines, a header "name [units],...", numeric rows), for the validation checks of the
// settling and swelling cases. Header-only; no physics here.
#pragma once
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ibms::validation {

// Columns by name without the " [units]" suffix, e.g. "time", "body_000/velocity_y".
using SeriesTable = std::map<std::string, std::vector<double>>;

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  return cells;
}

inline SeriesTable read_series_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  std::vector<std::string> names;
  SeriesTable table;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (names.empty()) {
      for (const std::string& c : cells) names.push_back(c.substr(0, c.find(" [")));
      continue;
    }
    if (cells.size() != names.size()) throw std::runtime_error(path + ": ragged row");
    for (std::size_t k = 0; k < cells.size(); ++k) {
      // A non-numeric cell is an error, not a 0 (issue 15 item 3).
      char* end = nullptr;
      const double value = std::strtod(cells[k].c_str(), &end);
      if (end == cells[k].c_str() || (*end != '\0' && *end != '\r' && *end != ' '))
        throw std::runtime_error(path + ": column " + names[k] + ": not a number: '" + cells[k] + "'");
      table[names[k]].push_back(value);
    }
  }
  if (names.empty() || table[names[0]].empty()) throw std::runtime_error(path + ": no data");
  return table;
}

// The value column `quantity` of a reference CSV (quantity,value,reading_uncertainty,units).
inline double reference_value(const std::string& path, const std::string& quantity) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (cells.size() >= 2 && cells[0] == quantity) {
      char* end = nullptr;
      const double value = std::strtod(cells[1].c_str(), &end);
      if (end == cells[1].c_str()) throw std::runtime_error(path + ": " + quantity + ": not a number: '" + cells[1] + "'");
      return value;
    }
  }
  throw std::runtime_error(path + ": no quantity " + quantity);
}

// First time at which `values` falls to `level` or below, linearly interpolated; < 0 if never.
inline double first_crossing_below(const std::vector<double>& time, const std::vector<double>& values, double level) {
  for (std::size_t k = 1; k < values.size(); ++k)
    if (values[k] <= level && values[k - 1] > level) {
      const double w = (values[k - 1] - level) / (values[k - 1] - values[k]);
      return time[k - 1] + w * (time[k] - time[k - 1]);
    }
  return -1.0;
}

}  // namespace ibms::validation
