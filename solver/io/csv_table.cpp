// CSV tables with units in the header (csv_table.hpp).
#include "io/csv_table.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace ibms {

void write_csv(const std::string& path, const std::vector<std::string>& comments,
               const std::vector<std::string>& column_headers,
               const std::vector<std::vector<double>>& columns) {
  if (column_headers.size() != columns.size()) {
    throw InputError(fmt::format("{}: {} column headers for {} columns", path, column_headers.size(), columns.size()));
  }
  const std::size_t n_rows = columns.empty() ? 0 : columns.front().size();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].size() != n_rows) {
      throw InputError(fmt::format("{}: column '{}' has {} rows, expected {}", path, column_headers[c],
                                   columns[c].size(), n_rows));
    }
  }
  std::string text;
  for (const std::string& comment : comments) {
    std::size_t start = 0;
    while (true) {
      const auto end = comment.find('\n', start);
      const std::string line = comment.substr(start, end == std::string::npos ? end : end - start);
      text += (line.rfind('#', 0) == 0 ? "" : "# ") + line + "\n";
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  text += fmt::format("{}\n", fmt::join(column_headers, ","));
  for (std::size_t row = 0; row < n_rows; ++row) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) text += ',';
      text += fmt::format("{:.17g}", columns[c][row]);
    }
    text += "\n";
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw OutputError(fmt::format("{}: cannot create CSV file: {}", path, std::strerror(errno)));
  errno = 0;
  file << text;
  file.close();
  if (!file) {
    const int reason = errno;
    std::remove(path.c_str());  // a truncated table would read as a shorter run
    throw OutputError(fmt::format("{}: cannot write CSV file: {}", path, reason != 0 ? std::strerror(reason) : "write failed"));
  }
}

}  // namespace ibms
