// Rows of a verification test's table appended as CSV to $IBMS_RESULTS_DIR/<file> for the report
// (the convergence_table mechanism of convergence.hpp for other tables, e.g. kernel_moments.csv).
// The header line goes out with the rows when the file is created; the block is one append-mode
// write, so tests running in parallel do not interleave rows. Nothing happens when the variable is
// unset; failures to write are reported on stderr, never thrown.
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace ibms::verification {

inline void append_results_csv(const std::string& file, const std::string& header,
                               const std::vector<std::string>& rows) {
  const char* dir = std::getenv("IBMS_RESULTS_DIR");
  if (dir == nullptr || *dir == '\0' || rows.empty()) return;
  const std::string path = std::string(dir) + "/" + file;
  std::string block;
  for (const std::string& r : rows) block += r + "\n";
  int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_EXCL, 0644);
  if (fd >= 0) block = header + "\n" + block;
  else fd = ::open(path.c_str(), O_WRONLY | O_APPEND);
  if (fd < 0) {
    std::fprintf(stderr, "append_results_csv: cannot append to %s\n", path.c_str());
    return;
  }
  if (::write(fd, block.data(), block.size()) != static_cast<ssize_t>(block.size()))
    std::fprintf(stderr, "append_results_csv: short write to %s\n", path.c_str());
  ::close(fd);
}

// One number as CSV text with full precision.
inline std::string csv_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace ibms::verification
