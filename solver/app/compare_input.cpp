// Strict CSV reader of `ibms compare` (compare_input.hpp).
#include "app/compare_input.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace ibms {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string column_name(const std::string& cell) {
  std::string name = trim(cell.substr(0, cell.find('[')));
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

}  // namespace

int CompareTable::find(const std::vector<std::string>& aliases) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (std::find(aliases.begin(), aliases.end(), names[c]) != aliases.end()) return static_cast<int>(c);
  return -1;
}

CompareTable read_compare_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  CompareTable t;
  t.path = path;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string stripped = trim(line);
    if (stripped.empty() || stripped[0] == '#') continue;
    const std::vector<std::string> cells = split(stripped);
    if (t.names.empty()) {
      for (const std::string& c : cells) {
        t.names.push_back(column_name(c));
        if (t.names.back().empty())
          throw InputError(path + ":" + std::to_string(line_number) + ": empty column name in the header");
      }
      t.columns.resize(t.names.size());
      t.header_line = line_number;
      continue;
    }
    if (cells.size() != t.names.size())
      throw InputError(path + ":" + std::to_string(line_number) + ": " + std::to_string(cells.size()) +
                       " values, the header has " + std::to_string(t.names.size()) + " columns");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string cell = trim(cells[c]);
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(cell.c_str(), &end);
      if (cell.empty() || end != cell.c_str() + cell.size() || errno == ERANGE || !std::isfinite(value))
        throw InputError(path + ":" + std::to_string(line_number) + ": column '" + t.names[c] +
                         "': not a finite number: '" + cell + "'");
      t.columns[c].push_back(value);
    }
    t.lines.push_back(line_number);
  }
  if (t.names.empty()) throw InputError(path + ": no header line (and no data)");
  if (t.lines.empty()) throw InputError(path + ":" + std::to_string(t.header_line) + ": header but no data rows");
  return t;
}

void require_increasing(const CompareTable& t, int c) {
  const std::vector<double>& x = t.columns[c];
  for (std::size_t k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      throw InputError(t.path + ":" + std::to_string(t.lines[k]) + ": column '" + t.names[c] +
                       "' must increase strictly (" + std::to_string(x[k]) + " after " + std::to_string(x[k - 1]) + ")");
}

}  // namespace ibms
