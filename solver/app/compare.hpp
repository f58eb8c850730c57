// `ibms compare CASE FILE...` (docs/compare.md): reads another code's CSV of a
// validation case's standard quantities, prints the metrics of the case's check against the
// published reference and against ibms's own high-resolution results shipped in
// validation/<case>/reference/, with tolerance and pass/fail. Returns 0 if every gated metric
// passes, 1 otherwise; bad input throws InputError (exit 2).
#pragma once
#include <string>
#include <vector>

namespace ibms {

// Names of the cases `ibms compare` knows.
std::vector<std::string> compare_case_names();

// validation_dir: the folder holding <case>/reference/ (source tree or installed share/ibms/validation).
int compare_case(const std::string& case_name, const std::vector<std::string>& files,
                 const std::string& validation_dir);

// Default validation folder: $IBMS_VALIDATION_DIR, else the source tree ibms was built from,
// else <prefix>/share/ibms/validation next to the running executable.
std::string default_validation_dir();

}  // namespace ibms
