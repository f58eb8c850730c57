// The result tables of the verification tests and the validation checks, one writer for both: rows
// appended as CSV through io/csv_table.hpp's appender (the header line goes out with the rows when
// the file is created; the block is one append-mode write, so programs running in parallel do not
// interleave rows). Nothing happens when the table's environment variable is unset; failures to
// write are reported on stderr, never thrown. Here, beside convergence.hpp (the convergence tables),
// rather than in solver/: the environment variables are ctest's, set by verification/CMakeLists.txt
// and validation/CMakeLists.txt, not the solver's.
//  - verification: $IBMS_RESULTS_DIR/<file>, e.g. kernel_moments.csv;
//  - validation: one line per check in $IBMS_VALIDATION_RESULTS (<build>/validation/results.csv:
//    case, "metric", tolerance, measured, pass|FAIL|info), the table the report's summary is built
//    from; a check run by hand without it still prints its figures.
#pragma once
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/csv_table.hpp"

namespace ibms {

namespace results {

// Appends rows to the table at path; `what` names the writer in a failure message.
inline void append_rows(const std::string& path, const std::string& header, const std::vector<std::string>& rows,
                        const char* what) {
  const std::string failure = append_csv_rows(path, header, rows);
  if (!failure.empty()) std::fprintf(stderr, "%s: %s\n", what, failure.c_str());
}

// The value of the environment variable `name`; empty when unset.
inline std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

}  // namespace results

namespace verification {

// Rows of a verification test's table to $IBMS_RESULTS_DIR/<file> for the report (the
// convergence_table mechanism of convergence.hpp for other tables).
inline void append_results_csv(const std::string& file, const std::string& header,
                               const std::vector<std::string>& rows) {
  const std::string dir = results::environment("IBMS_RESULTS_DIR");
  if (dir.empty() || rows.empty()) return;
  results::append_rows(dir + "/" + file, header, rows, "append_results_csv");
}

// One number as CSV text with full precision.
inline std::string csv_number(double value) { return ibms::csv_number(value); }

}  // namespace verification

namespace validation {

// One check's line to the table at path (nothing when path is empty); a NaN tolerance (info
// lines) is an empty column.
inline void append_result_line(const std::string& path, const std::string& name, const std::string& metric,
                               double tolerance, double measured, const char* verdict) {
  if (path.empty()) return;
  results::append_rows(path, "",
                       {csv_text(name) + "," + csv_text(metric, /*always_quote=*/true) + "," +
                        csv_number(tolerance, true) + "," + csv_number(measured) + "," + verdict},
                       "results.csv");
}

inline std::string results_path_from_environment() { return results::environment("IBMS_VALIDATION_RESULTS"); }

// pass/FAIL line to $IBMS_VALIDATION_RESULTS.
inline void record(const std::string& name, const std::string& metric, double tolerance, double measured, bool pass) {
  append_result_line(results_path_from_environment(), name, metric, tolerance, measured, pass ? "pass" : "FAIL");
}

// A reported figure without a pass/fail criterion (tolerance NaN: empty column).
inline void record_info(const std::string& name, const std::string& metric, double measured) {
  append_result_line(results_path_from_environment(), name, metric, NAN, measured, "info");
}

}  // namespace validation

}  // namespace ibms
