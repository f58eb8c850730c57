// One line per check in <build>/validation/results.csv (case, "metric", tolerance, measured,
// pass|FAIL|info), the table the report's summary is built from. Body-case checks find the file
// in $IBMS_VALIDATION_RESULTS (set by ctest, validation/CMakeLists.txt); without it they write
// nothing (a check run by hand still prints its figures).
#pragma once
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace ibms::validation {

inline void append_result_line(const std::string& path, const std::string& name, const std::string& metric,
                               double tolerance, double measured, const char* verdict) {
  if (path.empty()) return;
  std::ofstream out(path, std::ios::app);
  out.precision(8);
  out << name << ",\"" << metric << "\",";
  if (tolerance == tolerance) out << tolerance;  // NaN (info lines): empty column
  out << "," << measured << "," << verdict << "\n";
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
