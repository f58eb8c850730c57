// The one CSV reader (csv_reader.hpp).
#include "metrics/csv_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

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

// Cells of one line; double quotes group (and "" inside quotes is one quote). Throws on an
// unterminated quote.
std::vector<std::string> split(const std::string& line, const std::string& where) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '"') {
      if (quoted && k + 1 < line.size() && line[k + 1] == '"') {
        cells.back() += '"';
        ++k;
      } else {
        quoted = !quoted;
      }
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  if (quoted) throw InputError(where + "unterminated double quote");
  return cells;
}

}  // namespace

std::string CsvTable::where(int k) const {
  return path + ":" + std::to_string(k < 0 ? header_line : lines[static_cast<std::size_t>(k)]) + ": ";
}

int CsvTable::find(const std::vector<std::string>& aliases) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (std::find(aliases.begin(), aliases.end(), names[c]) != aliases.end()) return static_cast<int>(c);
  return -1;
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  const int c = find({name});
  if (c < 0) throw InputError(where() + "no column '" + name + "'");
  return column(c);
}

const std::vector<double>& CsvTable::column(int c) const {
  if (c < 0 || c >= static_cast<int>(names.size()))
    throw InputError(where() + "no column " + std::to_string(c + 1) + " (the header has " +
                     std::to_string(names.size()) + ")");
  if (!text[static_cast<std::size_t>(c)].empty() || (columns[static_cast<std::size_t>(c)].empty() && !lines.empty()))
    throw InputError(where() + "column '" + names[static_cast<std::size_t>(c)] + "' is text, not numbers");
  return columns[static_cast<std::size_t>(c)];
}

CsvTable read_csv(const std::string& path, const CsvOptions& options) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  CsvTable t;
  t.path = path;
  std::vector<bool> is_text;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string stripped = trim(line);
    if (stripped.empty() || stripped[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    const std::vector<std::string> cells = split(stripped, where);
    if (t.names.empty()) {
      for (const std::string& c : cells) {
        t.names.push_back(column_name(c));
        if (t.names.back().empty()) throw InputError(where + "empty column name in the header");
        is_text.push_back(std::find(options.text_columns.begin(), options.text_columns.end(), t.names.back()) !=
                          options.text_columns.end());
      }
      t.columns.resize(t.names.size());
      t.text.resize(t.names.size());
      t.header_line = line_number;
      continue;
    }
    if (cells.size() != t.names.size())
      throw InputError(where + std::to_string(cells.size()) + " values, the header has " +
                       std::to_string(t.names.size()) + " columns");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string cell = trim(cells[c]);
      if (is_text[c]) {
        t.text[c].push_back(cell);
        continue;
      }
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(cell.c_str(), &end);
      if (cell.empty() || end != cell.c_str() + cell.size() || errno == ERANGE || !std::isfinite(value))
        throw InputError(where + "column '" + t.names[c] + "': not a finite number: '" + cell + "'");
      t.columns[c].push_back(value);
    }
    t.lines.push_back(line_number);
  }
  if (t.names.empty()) throw InputError(path + ": no header line (and no data)");
  if (t.lines.empty()) throw InputError(path + ":" + std::to_string(t.header_line) + ": header but no data rows");
  return t;
}

void require_increasing(const CsvTable& t, int c) {
  const std::vector<double>& x = t.column(c);
  for (std::size_t k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      throw InputError(t.where(static_cast<int>(k)) + "column '" + t.names[static_cast<std::size_t>(c)] +
                       "' must increase strictly (" + std::to_string(x[k]) + " after " + std::to_string(x[k - 1]) + ")");
}

double reference_value(const std::string& path, const std::string& quantity, const std::string& column) {
  const CsvTable t = read_csv(path, {{"quantity", "units", "basis", "source", "exact_value"}});
  const int q = t.find({"quantity"}), v = t.find({column});
  if (q < 0 || v < 0) throw InputError(t.where() + "a reference file needs the columns quantity and " + column);
  for (std::size_t k = 0; k < t.rows(); ++k)
    if (t.text[static_cast<std::size_t>(q)][k] == quantity) return t.columns[static_cast<std::size_t>(v)][k];
  throw InputError(path + ": no quantity '" + quantity + "'");
}

}  // namespace ibms
