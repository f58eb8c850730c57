// `ibms compare` for the two body-cavity validation cases (docs/compare.md):
//   cavity_swelling_particles NONSWELLING.csv SWELLING.csv   (time,particle,x,y[,diameter])
//   cavity_deformable_objects K10.csv K100.csv               (time,particle,deformation[,area_ratio])
// Each file may also be ibms's own wide <stem>_bodies.csv (columns body_NNN/...). The metrics and
// thresholds are those of validation/<case>/check.cpp; ibms's own results of the validation runs
// (validation/<case>/reference/, README_ibms.md there) are printed beside them. Return 0 if every
// gated metric passes, 1 otherwise; bad input throws InputError "FILE:LINE: reason".
#pragma once
#include <string>
#include <vector>

namespace ibms {

int compare_swelling_particles(const std::vector<std::string>& files, const std::string& validation_dir);
int compare_deformable_objects(const std::vector<std::string>& files, const std::string& validation_dir);

}  // namespace ibms
