// Strict reading of another code's CSV for `ibms compare` (docs/compare.md): '#' comment lines and
// blank lines skipped, one header line of comma-separated column names (an optional " [units]"
// suffix is ignored, names compare case-insensitively), then numeric rows of the same width.
// Every defect throws InputError "FILE:LINE: reason" (exit 2 in the command line).
#pragma once
#include <string>
#include <vector>

namespace ibms {

struct CompareTable {
  std::string path;
  std::vector<std::string> names;            // lower-case, units stripped
  std::vector<std::vector<double>> columns;  // one per name
  std::vector<int> lines;                    // file line of each row (for messages)
  int header_line = 0;

  // Index of the first column whose name is one of `aliases`; -1 if none.
  int find(const std::vector<std::string>& aliases) const;
};

CompareTable read_compare_csv(const std::string& path);

// Checks that column `c` is strictly increasing (an abscissa); throws InputError naming the row.
void require_increasing(const CompareTable& table, int c);

}  // namespace ibms
