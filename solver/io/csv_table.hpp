// Small derived tables (centre-line profiles, trajectories) as CSV (DESIGN.md §5): comment lines
// beginning with '#' first, then a header naming columns with units ("y [length],u [length/time]"),
// then one row per index, numbers as %.17g so they read back exactly.
#pragma once
#include <string>
#include <vector>

namespace ibms {

// Column c of the table is columns[c] with header column_headers[c]; all columns have one length.
// Comments may span lines; each line gets a leading "# " unless it already starts with '#'.
// Throws InputError "<path>: <reason>" on mismatched sizes or when the file cannot be written.
void write_csv(const std::string& path, const std::vector<std::string>& comments,
               const std::vector<std::string>& column_headers,
               const std::vector<std::vector<double>>& columns);

}  // namespace ibms
