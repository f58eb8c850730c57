// Rows of a verification test's table appended as CSV to $IBMS_RESULTS_DIR/<file> for the report
// (the convergence_table mechanism of convergence.hpp for other tables, e.g. kernel_moments.csv).
// The header line goes out with the rows when the file is created; the block is one append-mode
// write, so tests running in parallel do not interleave rows. Nothing happens when the variable is
// unset; failures to write are reported on stderr, never thrown.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/csv_table.hpp"

namespace ibms::verification {

inline void append_results_csv(const std::string& file, const std::string& header,
                               const std::vector<std::string>& rows) {
  const char* dir = std::getenv("IBMS_RESULTS_DIR");
  if (dir == nullptr || *dir == '\0' || rows.empty()) return;
  const std::string failure = append_csv_rows(std::string(dir) + "/" + file, header, rows);
  if (!failure.empty()) std::fprintf(stderr, "append_results_csv: %s\n", failure.c_str());
}

// One number as CSV text with full precision.
inline std::string csv_number(double value) { return ibms::csv_number(value); }

}  // namespace ibms::verification
