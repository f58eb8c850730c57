// CSV tables with units in the header (csv_table.hpp).
#include "io/csv_table.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
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

std::string append_csv_rows(const std::string& path, const std::string& header, const std::vector<std::string>& rows) {
  if (rows.empty()) return "";
  std::string block;
  for (const std::string& r : rows) block += r + "\n";
  int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_EXCL, 0644);
  if (fd >= 0) {
    if (!header.empty()) block = header + "\n" + block;
  } else {
    fd = ::open(path.c_str(), O_WRONLY | O_APPEND);
  }
  if (fd < 0) return fmt::format("{}: cannot append: {}", path, std::strerror(errno));
  const ssize_t written = ::write(fd, block.data(), block.size());
  const int reason = errno;
  ::close(fd);
  if (written != static_cast<ssize_t>(block.size()))
    return fmt::format("{}: short write: {}", path, written < 0 ? std::strerror(reason) : "disk full?");
  return "";
}

std::string csv_text(const std::string& text, bool always_quote) {
  if (!always_quote && text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_number(double value, bool nan_empty) {
  if (nan_empty && std::isnan(value)) return "";
  return fmt::format("{:.17g}", value);
}

}  // namespace ibms
