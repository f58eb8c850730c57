// Check of a lid-driven cavity case against Ghia, Ghia & Shin (1982) and of the antiparallel
// two-sided cavity against its exact symmetry constraints (docs/design.md §7). Reads the centre-line
// CSV files that `ibms run` wrote for three grids (coarse, medium, fine; refinement ratio 2),
// prints the metric, the grid convergence index of Celik et al. (2008) of the profile extrema,
// appends a result line to a CSV for the report, and exits non-zero on failure.
//
// usage: cavity_check ghia <case> <ref_u.csv> <ref_v.csv> <results.csv> <base_coarse> <base_medium> <base_fine>
//        (and against Botella & Peyret where botella_peyret_extrema.csv lies beside ref_u.csv)
//        cavity_check symmetry <case> <results.csv> <constraints.csv> <base_coarse> <base_medium> <base_fine>
// <case> names the case in results.csv; the tolerance is the case's (for <case>_<suffix>, that
// case's), from solver/metrics/case_criteria.hpp (one definition with `ibms compare`); profiles are
// interpolated and their extrema located by metrics/profile.hpp.
// The symmetry mode checks every row of <constraints.csv> (quantity,exact_value,basis) it knows;
// a row it does not know is an error (a constraint added to the file cannot be skipped silently),
// except a non-numeric exact value, which is reported as information.
// where <base> is the HDF5 output path without ".h5" (profiles are <base>_centreline_u/v.csv).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "metrics/grid_convergence.hpp"
#include "metrics/profile.hpp"
#include "verification/common/results_csv.hpp"

using namespace ibms;

namespace {

using Table = ProfileTable;

struct Profiles { Table u, v; };

Profiles read_profiles(const std::string& base) {
  return {read_profile_table(base + "_centreline_u.csv"), read_profile_table(base + "_centreline_v.csv")};
}

// The tolerance of the case that <name> is, or that <name> starts with followed by '_' (the results
// name of a check at another label: lid_driven_cavity_re1000_slow).
double case_tolerance(const std::string& name) {
  for (const criteria::CavityCase& c : criteria::cavity_cases)
    if (name == c.name || name.rfind(std::string(c.name) + "_", 0) == 0) return c.tolerance;
  throw std::runtime_error("case '" + name + "' has no criteria in solver/metrics/case_criteria.hpp");
}

void append_result(const std::string& path, const std::string& name, const std::string& metric, double tolerance,
                   double measured, bool pass) {
  validation::append_result_line(path, name, metric, tolerance, measured, pass ? "pass" : "FAIL");
}

// GCI of scalar profile quantities: an extremum (min/max) or the value at a point.
struct Quantity { const char* label; bool use_u; enum Kind { minimum, maximum, value_at } kind; double at; };

void report_gci(const std::vector<Profiles>& grids, const std::string& results, const std::string& name,
                const std::vector<Quantity>& quantities) {
  for (const Quantity& q : quantities) {
    double phi[3];
    for (int k = 0; k < 3; ++k) {
      const Table& t = q.use_u ? grids[k].u : grids[k].v;
      const ProfileSpline spline(t.s, t.f);
      phi[k] = q.kind == Quantity::value_at ? spline(q.at) : spline.extremum(q.kind == Quantity::maximum);
    }
    // Spacings in units of the fine one (refinement ratio 2 between the grids).
    const GridConvergence g = grid_convergence(1.0, 2.0, 4.0, phi[2], phi[1], phi[0], fluid_order);
    std::printf("  %-18s coarse %.6f  medium %.6f  fine %.6f  observed order %.2f  extrapolated %.6f  GCI_fine %.3f %%%s\n",
                q.label, phi[0], phi[1], phi[2], g.order, g.extrapolated, 100 * g.gci_fine,
                g.converging ? "" : g.monotone ? "  (the differences do not shrink: no order, no GCI)"
                                               : "  (non-monotone convergence: no order, no GCI)");
    // Reported, not gated: the GCI estimates our own discretisation error (docs/design.md §6).
    char metric[160];
    std::snprintf(metric, sizeof metric, "GCI_fine of %s (observed order %.6g)", q.label, g.order);
    validation::append_result_line(results, name, metric, NAN, g.gci_fine, "info");
  }
}

// Against the spectral centre-line extrema of Botella & Peyret (1998), where the case's reference
// folder holds them (reference/botella_peyret_extrema.csv beside the Ghia profile): accurate to
// 1e-7, so that the grids are told apart, which Ghia's table (itself a 129^2 / 257^2 solution) cannot.
// The largest error of {u_min, v_max, v_min} must at least halve at each grid halving (convergence
// at better than first order toward the published values); the observed orders are reported.
// Returns true when there is no such file.
bool check_botella_peyret(const std::string& ghia_u_path, const std::vector<Profiles>& grids,
                          const std::string& results, const std::string& name) {
  const std::size_t slash = ghia_u_path.find_last_of('/');
  const std::string path = (slash == std::string::npos ? std::string() : ghia_u_path.substr(0, slash + 1)) +
                           "botella_peyret_extrema.csv";
  if (!std::ifstream(path)) return true;
  const std::array<double, 3> published = published_extrema(path);
  std::printf("centre-line extrema against Botella & Peyret (1998), cubic-spline extrema:\n");
  std::printf("  %8s %10s %10s %10s %12s %8s\n", "grid", "u_min", "v_max", "v_min", "largest err", "order");
  bool pass = true;
  double previous = NAN;
  for (std::size_t k = 0; k < grids.size(); ++k) {
    const Profiles& g = grids[k];
    const std::array<double, 3> measured = centreline_extrema(g.u.s, g.u.f, g.v.s, g.v.f);
    const double error = largest_extremum_error(measured, published);
    const double order = k > 0 ? std::log2(previous / error) : NAN;
    const std::string cells = std::to_string(g.v.s.size() - 2) + "^2";  // profile points: cells + 2 walls
    std::printf("  %8s %10.6f %10.6f %10.6f %12.3e %8.2f\n", cells.c_str(), measured[0], measured[1], measured[2],
                error, order);
    char metric[200];
    if (k == 0) {
      std::snprintf(metric, sizeof metric, "largest |centre-line extremum - Botella & Peyret| on %s", cells.c_str());
      validation::append_result_line(results, name, metric, NAN, error, "info");
    } else {
      const bool halves = error <= 0.5 * previous;
      pass = pass && halves;
      std::snprintf(metric, sizeof metric,
                    "largest |centre-line extremum - Botella & Peyret| on %s, at most half the coarser grid's "
                    "(convergence order %.3g)", cells.c_str(), order);
      append_result(results, name, metric, 0.5 * previous, error, halves);
    }
    previous = error;
  }
  std::printf("the largest error halves at every refinement: %s\n", pass ? "pass" : "FAIL");
  return pass;
}

int check_ghia(char** argv) {
  const std::string name = argv[2];
  const double tolerance = case_tolerance(name);
  const Table ref_u = read_profile_table(argv[3]), ref_v = read_profile_table(argv[4]);
  const std::string results = argv[5];
  std::vector<Profiles> grids;
  for (int k = 0; k < 3; ++k) grids.push_back(read_profiles(argv[6 + k]));
  const Profiles& fine = grids[2];
  std::printf("%s: centre-line velocity against Ghia et al. (1982), flagged points excluded\n", name.c_str());
  std::printf("  %8s %10s %10s %10s\n", "coord", "ghia", "ibms", "|diff|");
  double worst = 0;
  for (int comp = 0; comp < 2; ++comp) {
    const Table& ref = comp == 0 ? ref_u : ref_v;
    const Table& ours = comp == 0 ? fine.u : fine.v;
    std::printf("  %s\n", comp == 0 ? "u(0.5, y):" : "v(x, 0.5):");
    const ProfileSpline spline(ours.s, ours.f);
    for (std::size_t k = 0; k < ref.s.size(); ++k) {
      const double c = ref.s[k], value = spline(c);
      const double diff = std::abs(value - ref.f[k]);
      const bool flagged = !ref.flags[k].empty();
      std::printf("  %8.4f %10.5f %10.5f %10.5f%s\n", c, ref.f[k], value, diff,
                  flagged ? "  (flagged in the reference: excluded)" : "");
      if (!flagged) worst = std::max(worst, diff);
    }
  }
  const bool pass = worst <= tolerance;
  std::printf("max deviation from Ghia: %.5f (tolerance %.3f): %s\n", worst, tolerance, pass ? "pass" : "FAIL");
  append_result(results, name, "max |centre-line velocity - Ghia| (lid speed 1)", tolerance, worst, pass);
  const bool converges = check_botella_peyret(argv[3], grids, results, name);
  std::printf("grid convergence (Celik et al. 2008, safety factor 1.25, r = 2):\n");
  // Extrema of the centre-line profiles (wall values excluded by being interior extrema).
  report_gci(grids, results, name,
             {{"min u on x = 0.5", true, Quantity::minimum, 0}, {"max v on y = 0.5", false, Quantity::maximum, 0},
              {"min v on y = 0.5", false, Quantity::minimum, 0}});
  return pass && converges ? 0 : 1;
}

// Rows of a constraints file: quantity (quoted), exact value, basis (read_csv; all text).
struct Constraint { std::string quantity, exact; };

std::vector<Constraint> read_constraints(const std::string& path) {
  const CsvTable t = read_csv(path, {{"quantity", "exact_value", "basis"}});
  const int q = t.find({"quantity"}), e = t.find({"exact_value"});
  if (q < 0 || e < 0) throw std::runtime_error(t.where() + "expected the columns quantity,exact_value,basis");
  std::vector<Constraint> rows;
  for (std::size_t k = 0; k < t.rows(); ++k)
    rows.push_back({t.text[static_cast<std::size_t>(q)][k], t.text[static_cast<std::size_t>(e)][k]});
  return rows;
}

// Checks the constraints that the fine grid's centre-line profiles can show; returns the largest
// defect |measured - exact| over them and prints each.
double check_constraints(const std::string& path, const Profiles& fine, double symmetry_defect_u,
                         double symmetry_defect_v) {
  const std::vector<double>& y = fine.u.s;
  const std::vector<double>& u = fine.u.f;
  const double u_centre = ProfileSpline(y, u)(0.5);
  const double v_centre = ProfileSpline(fine.v.s, fine.v.f)(0.5);
  double flux = 0.0;  // trapezoid over the profile points, walls included
  for (std::size_t k = 0; k + 1 < y.size(); ++k) flux += 0.5 * (u[k] + u[k + 1]) * (y[k + 1] - y[k]);
  double worst = 0.0;
  for (const Constraint& c : read_constraints(path)) {
    char* end = nullptr;
    const double exact = std::strtod(c.exact.c_str(), &end);
    const bool numeric = end != c.exact.c_str() && *end == '\0';
    double measured = NAN;
    if (c.quantity == "u(x,1) on top lid") measured = u.back();
    else if (c.quantity == "u(x,0) on bottom lid") measured = u.front();
    else if (c.quantity == "u(0.5,0.5)") measured = u_centre;
    else if (c.quantity == "v(0.5,0.5)") measured = v_centre;
    else if (c.quantity == "u(0.5,y) + u(0.5,1-y)") measured = symmetry_defect_u;
    else if (c.quantity == "v(x,0.5) + v(1-x,0.5)") measured = symmetry_defect_v;
    else if (c.quantity == "integral_0^1 u(0.5,y) dy") measured = flux;
    else if (c.quantity == "primary vortex center") measured = std::max(std::abs(u_centre), std::abs(v_centre));
    else if (!numeric) {
      std::printf("  constraint %-28s %s (information only: not a value)\n", c.quantity.c_str(), c.exact.c_str());
      continue;
    } else {
      throw std::runtime_error(path + ": constraint '" + c.quantity + "' is not known to cavity_check");
    }
    // The vortex centre (0.5, 0.5) is checked as u = v = 0 there.
    const double defect = c.quantity == "primary vortex center" ? measured : std::abs(measured - exact);
    std::printf("  constraint %-28s exact %-10s measured %+.3e  defect %.3e\n", c.quantity.c_str(), c.exact.c_str(),
                measured, defect);
    worst = std::max(worst, defect);
  }
  return worst;
}

int check_symmetry(char** argv) {
  const std::string name = argv[2];
  const double tolerance = criteria::cavity_symmetry_tolerance;
  const std::string results = argv[3];
  const std::string constraints = argv[4];
  std::vector<Profiles> grids;
  for (int k = 0; k < 3; ++k) grids.push_back(read_profiles(argv[5 + k]));
  const Profiles& fine = grids[2];
  // Point symmetry u(1-x, 1-y) = -u(x, y) restricted to the centre lines: u(0.5, 1-y) = -u(0.5, y)
  // and v(1-x, 0.5) = -v(x, 0.5); at the centre u = v = 0. Profile points are symmetric in y and x.
  double worst = 0;
  double defect[2] = {0.0, 0.0};
  for (int comp = 0; comp < 2; ++comp) {
    const std::vector<double>& f = (comp == 0 ? fine.u : fine.v).f;
    for (std::size_t k = 0; k < f.size(); ++k) defect[comp] = std::max(defect[comp], std::abs(f[k] + f[f.size() - 1 - k]));
    worst = std::max(worst, defect[comp]);
  }
  const double u_centre = ProfileSpline(fine.u.s, fine.u.f)(0.5);
  const double v_centre = ProfileSpline(fine.v.s, fine.v.f)(0.5);
  worst = std::max({worst, std::abs(u_centre), std::abs(v_centre)});
  const bool pass = worst <= tolerance;
  std::printf("%s: u(0.5,0.5) = %.3e, v(0.5,0.5) = %.3e, max centre-line symmetry defect %.3e (tolerance %.1e): %s\n",
              name.c_str(), u_centre, v_centre, worst, tolerance, pass ? "pass" : "FAIL");
  append_result(results, name, "max centre-line point-symmetry defect", tolerance, worst, pass);
  // Every constraint of the case's reference file (lid values, centre, odd profiles, zero net flux
  // through x = 0.5, vortex centre), read and checked, not only the point symmetry.
  std::printf("constraints of %s:\n", constraints.c_str());
  const double constraint_defect = check_constraints(constraints, fine, defect[0], defect[1]);
  const bool constraints_pass = constraint_defect <= tolerance;
  std::printf("%s: largest constraint defect %.3e (tolerance %.1e): %s\n", name.c_str(), constraint_defect, tolerance,
              constraints_pass ? "pass" : "FAIL");
  append_result(results, name, "largest defect of reference/constraints (lids, centre, odd profiles, net flux)",
                tolerance, constraint_defect, constraints_pass);
  std::printf("grid convergence (Celik et al. 2008, safety factor 1.25, r = 2):\n");
  // u's extrema on x = 0.5 are the lid values, so use interior point values instead.
  report_gci(grids, results, name,
             {{"u(0.5, 0.75)", true, Quantity::value_at, 0.75}, {"max v on y = 0.5", false, Quantity::maximum, 0}});
  return pass && constraints_pass ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "ghia" && argc == 9) return check_ghia(argv);
    if (mode == "symmetry" && argc == 8) return check_symmetry(argv);
    std::fprintf(stderr, "usage: see the comment at the top of validation/common/cavity_check.cpp\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cavity_check: %s\n", e.what());
    return 2;
  }
}
