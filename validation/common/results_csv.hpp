// One line per check in <build>/validation/results.csv (case, "metric", tolerance, measured,
// pass|FAIL|info), the table the report's summary is built from. Body-case checks find the file
// in $IBMS_VALIDATION_RESULTS (set by ctest, validation/CMakeLists.txt); without it they write
// nothing (a check run by hand still prints its figures).
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/csv_table.hpp"

namespace ibms::validation {

// Through the one appender (io/csv_table.hpp: one write per line, no interleaving); a NaN
// tolerance (info lines) is an empty column.
inline void append_result_line(const std::string& path, const std::string& name, const std::string& metric,
                               double tolerance, double measured, const char* verdict) {
  if (path.empty()) return;
  const std::string failure = append_csv_rows(
      path, "", {csv_text(name) + "," + csv_text(metric, /*always_quote=*/true) + "," + csv_number(tolerance, true) + "," +
                 csv_number(measured) + "," + verdict});
  if (!failure.empty()) std::fprintf(stderr, "results.csv: %s\n", failure.c_str());
}

inline std::string results_path_from_environment() {
  const char* path = std::getenv("IBMS_VALIDATION_RESULTS");
  return path ? std::string(path) : std::string();
}

// pass/FAIL line to $IBMS_VALIDATION_RESULTS.
inline void record(const std::string& name, const std::string& metric, double tolerance, double measured, bool pass) {
  append_result_line(results_path_from_environment(), name, metric, tolerance, measured, pass ? "pass" : "FAIL");
}

// A reported figure without a pass/fail criterion (tolerance NaN: empty column).
inline void record_info(const std::string& name, const std::string& metric, double measured) {
  append_result_line(results_path_from_environment(), name, metric, NAN, measured, "info");
}

}  // namespace ibms::validation
