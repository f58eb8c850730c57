// Check of a lid-driven cavity case against Ghia, Ghia & Shin (1982) and of the antiparallel
// two-sided cavity against its exact symmetry constraints (DESIGN.md §7). Reads the centre-line
// CSV files that `ibms run` wrote for three grids (coarse, medium, fine; refinement ratio 2),
// prints the metric, the grid convergence index of Celik et al. (2008) of the profile extrema,
// appends a result line to a CSV for the report, and exits non-zero on failure.
//
// usage: cavity_check ghia <case> <tolerance> <ref_u.csv> <ref_v.csv> <results.csv> <base_coarse> <base_medium> <base_fine>
//        cavity_check symmetry <case> <tolerance> <results.csv> <base_coarse> <base_medium> <base_fine>
// where <base> is the HDF5 output path without ".h5" (profiles are <base>_centreline_u/v.csv).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "profile_table.hpp"

using namespace ibms::validation;

namespace {

struct Profiles { Table u, v; };

Profiles read_profiles(const std::string& base) {
  return {read_table(base + "_centreline_u.csv"), read_table(base + "_centreline_v.csv")};
}

void append_result(const std::string& path, const std::string& name, const std::string& metric, double tolerance,
                   double measured, bool pass) {
  std::ofstream out(path, std::ios::app);
  out << name << ",\"" << metric << "\"," << tolerance << "," << measured << "," << (pass ? "pass" : "FAIL") << "\n";
}

// GCI of scalar profile quantities: an extremum (min/max) or the value at a point.
struct Quantity { const char* label; bool use_u; enum Kind { minimum, maximum, value_at } kind; double at; };

void report_gci(const std::vector<Profiles>& grids, const std::string& results, const std::string& name,
                const std::vector<Quantity>& quantities) {
  for (const Quantity& q : quantities) {
    double phi[3];
    for (int k = 0; k < 3; ++k) {
      const Table& t = q.use_u ? grids[k].u : grids[k].v;
      phi[k] = q.kind == Quantity::value_at ? interpolate(t.columns[0], t.columns[1], q.at)
                                            : profile_extremum(t.columns[0], t.columns[1], q.kind == Quantity::maximum);
    }
    const GciResult g = grid_convergence_index(phi[0], phi[1], phi[2], 2.0);
    std::printf("  %-18s coarse %.6f  medium %.6f  fine %.6f  observed order %.2f  extrapolated %.6f  GCI_fine %.3f %%%s\n",
                q.label, phi[0], phi[1], phi[2], g.observed_order, g.extrapolated, 100 * g.gci_fine,
                g.monotone ? "" : "  (non-monotone convergence: GCI not meaningful)");
    // Reported, not gated: the GCI estimates our own discretisation error (DESIGN.md §6).
    std::ofstream(results, std::ios::app) << name << ",\"GCI_fine of " << q.label << " (observed order "
                                          << g.observed_order << ")\",," << g.gci_fine << ",info\n";
  }
}

int check_ghia(char** argv) {
  const std::string name = argv[2];
  const double tolerance = std::atof(argv[3]);
  const Table ref_u = read_table(argv[4]), ref_v = read_table(argv[5]);
  const std::string results = argv[6];
  std::vector<Profiles> grids;
  for (int k = 0; k < 3; ++k) grids.push_back(read_profiles(argv[7 + k]));
  const Profiles& fine = grids[2];
  std::printf("%s: centre-line velocity against Ghia et al. (1982), flagged points excluded\n", name.c_str());
  std::printf("  %8s %10s %10s %10s\n", "coord", "ghia", "ibms", "|diff|");
  double worst = 0;
  for (int comp = 0; comp < 2; ++comp) {
    const Table& ref = comp == 0 ? ref_u : ref_v;
    const Table& ours = comp == 0 ? fine.u : fine.v;
    std::printf("  %s\n", comp == 0 ? "u(0.5, y):" : "v(x, 0.5):");
    for (std::size_t k = 0; k < ref.columns[0].size(); ++k) {
      const double c = ref.columns[0][k], value = interpolate(ours.columns[0], ours.columns[1], c);
      const double diff = std::abs(value - ref.columns[1][k]);
      const bool flagged = !ref.flags[k].empty();
      std::printf("  %8.4f %10.5f %10.5f %10.5f%s\n", c, ref.columns[1][k], value, diff,
                  flagged ? "  (flagged in the reference: excluded)" : "");
      if (!flagged) worst = std::max(worst, diff);
    }
  }
  const bool pass = worst <= tolerance;
  std::printf("max deviation from Ghia: %.5f (tolerance %.3f): %s\n", worst, tolerance, pass ? "pass" : "FAIL");
  append_result(results, name, "max |centre-line velocity - Ghia| (lid speed 1)", tolerance, worst, pass);
  std::printf("grid convergence (Celik et al. 2008, safety factor 1.25, r = 2):\n");
  // Extrema of the centre-line profiles (wall values excluded by being interior extrema).
  report_gci(grids, results, name,
             {{"min u on x = 0.5", true, Quantity::minimum, 0}, {"max v on y = 0.5", false, Quantity::maximum, 0},
              {"min v on y = 0.5", false, Quantity::minimum, 0}});
  return pass ? 0 : 1;
}

int check_symmetry(char** argv) {
  const std::string name = argv[2];
  const double tolerance = std::atof(argv[3]);
  const std::string results = argv[4];
  std::vector<Profiles> grids;
  for (int k = 0; k < 3; ++k) grids.push_back(read_profiles(argv[5 + k]));
  const Profiles& fine = grids[2];
  // Point symmetry u(1-x, 1-y) = -u(x, y) restricted to the centre lines: u(0.5, 1-y) = -u(0.5, y)
  // and v(1-x, 0.5) = -v(x, 0.5); at the centre u = v = 0. Profile points are symmetric in y and x.
  double worst = 0;
  for (int comp = 0; comp < 2; ++comp) {
    const std::vector<double>& f = (comp == 0 ? fine.u : fine.v).columns[1];
    for (std::size_t k = 0; k < f.size(); ++k) worst = std::max(worst, std::abs(f[k] + f[f.size() - 1 - k]));
  }
  const double u_centre = interpolate(fine.u.columns[0], fine.u.columns[1], 0.5);
  const double v_centre = interpolate(fine.v.columns[0], fine.v.columns[1], 0.5);
  worst = std::max({worst, std::abs(u_centre), std::abs(v_centre)});
  const bool pass = worst <= tolerance;
  std::printf("%s: u(0.5,0.5) = %.3e, v(0.5,0.5) = %.3e, max centre-line symmetry defect %.3e (tolerance %.1e): %s\n",
              name.c_str(), u_centre, v_centre, worst, tolerance, pass ? "pass" : "FAIL");
  append_result(results, name, "max centre-line point-symmetry defect", tolerance, worst, pass);
  std::printf("grid convergence (Celik et al. 2008, safety factor 1.25, r = 2):\n");
  // u's extrema on x = 0.5 are the lid values, so use interior point values instead.
  report_gci(grids, results, name,
             {{"u(0.5, 0.75)", true, Quantity::value_at, 0.75}, {"max v on y = 0.5", false, Quantity::maximum, 0}});
  return pass ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "ghia" && argc == 10) return check_ghia(argv);
    if (mode == "symmetry" && argc == 8) return check_symmetry(argv);
    std::fprintf(stderr, "usage: see the comment at the top of validation/common/cavity_check.cpp\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cavity_check: %s\n", e.what());
    return 2;
  }
}
