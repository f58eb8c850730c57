// The one CSV reader of ibms's tables: `ibms compare`'s input, the validation
// checks' run outputs (<stem>_bodies.csv, centre-line profiles) and the references they compare
// with (published tables, quantity files, constraints) all go through read_csv.
//  - '#' comment lines and blank lines are skipped;
//  - the first other line is the header: comma-separated column names; a " [units]" suffix is
//    dropped and names compare case-insensitively (stored lower-case);
//  - every following line is a row of exactly as many cells; a cell may be double-quoted (then it
//    may hold commas; "" is a quote);
//  - every cell is a finite decimal number, except in the columns named as text (CsvOptions).
// Every defect throws InputError "FILE:LINE: reason" naming the column and the cell.
#pragma once
#include <string>
#include <vector>

namespace ibms {

struct CsvOptions {
  std::vector<std::string> text_columns;  // lower-case names whose cells are kept as text
};

struct CsvTable {
  std::string path;
  std::vector<std::string> names;                 // lower-case, units stripped
  std::vector<std::vector<double>> columns;       // one per name (empty for a text column)
  std::vector<std::vector<std::string>> text;     // one per name (empty for a numeric column)
  std::vector<int> lines;                         // file line of each row (for messages)
  int header_line = 0;

  std::size_t rows() const { return lines.size(); }
  // Index of the first column whose name is one of `aliases`; -1 if none.
  int find(const std::vector<std::string>& aliases) const;
  // The numeric column `name`; throws InputError naming the file when it is missing.
  const std::vector<double>& column(const std::string& name) const;
  // The numeric column at position c (0-based); throws InputError when there is none.
  const std::vector<double>& column(int c) const;
  // "FILE:LINE: " of row k (k < 0: the header line).
  std::string where(int k = -1) const;
};

CsvTable read_csv(const std::string& path, const CsvOptions& options = {});

// Checks that column `c` is strictly increasing (an abscissa); throws InputError naming the row.
void require_increasing(const CsvTable& table, int c);

// The `value` of the row whose `quantity` is `quantity` in a reference file
// (quantity,value[,...]; other columns numeric unless named units, basis, source or position
// text); throws InputError when the quantity is missing. `column` reads another numeric column of
// that row instead (lower, upper: the published bounds).
double reference_value(const std::string& path, const std::string& quantity, const std::string& column = "value");

}  // namespace ibms
