// Small derived tables (centre-line profiles, trajectories) as CSV (docs/design.md §5): comment lines
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

// Result tables that several programs append to (validation/results.csv, the verification
// tables of the report): `rows` (CSV lines without their newline) go to the end of `path` in one
// append-mode write, so programs running in parallel do not interleave rows; `header` (if not
// empty) goes first when this call creates the file. Returns "" on success, else the reason (the
// callers report it and go on: a missing report table must not fail a test).
std::string append_csv_rows(const std::string& path, const std::string& header, const std::vector<std::string>& rows);

// One CSV cell: text double-quoted (with "" for a quote) when it holds a comma, quote or newline,
// or always when `always_quote`; numbers with 17 significant digits (they read back exactly), or
// an empty cell for NaN when `nan_empty`.
std::string csv_text(const std::string& text, bool always_quote = false);
std::string csv_number(double value, bool nan_empty = false);

}  // namespace ibms
