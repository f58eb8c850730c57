// `ibms compare` for the DFG cylinder benchmarks (docs/compare.md): dfg_cylinder_2d1 (the steady
// coefficients, last row of the file) and dfg_cylinder_2d2 (the force history; figures over its
// last 4 time units by metrics/force_metrics.hpp, the definition the case checks use).
#pragma once
#include <string>
#include <vector>

namespace ibms {

int compare_dfg_steady(const std::vector<std::string>& files, const std::string& validation_dir);
int compare_dfg_periodic(const std::vector<std::string>& files, const std::string& validation_dir);

}  // namespace ibms
