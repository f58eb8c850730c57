// Check of the one-sided cavity with deformable objects (README.md): reads the body
// series of the k = 10 and k = 100 runs and verifies, for each run,
//   1. it reached end_time (no blow-up: no point left the box, nothing non-finite);
//   2. the wall contacts keep the bodies in the box: the smallest rim-point distance to a wall
//      stays >= r_c / 2 (r_c = 0.04, the CDS radius: contact starts at r_c);
//   3. the body contacts keep the bodies apart: the smallest rim-point distance between different
//      bodies stays >= r_c (contact starts at 2 r_c), no rim point inside another body's rim
//      polygon and no crossing rim edges between bodies (sampled at every output step);
//   3b. no rim folds through itself (no two edges of one rim cross; the papers' model has no
//      self-contact): a gate for k = 100; for k = 10 the first time a rim folds is recorded
//      (README.md: the soft body squeezed in the lid's corner folds before t = 20);
//   4. areas stay bounded: every body's rim-polygon area stays within [0.5, 1.5] A0 (the wheel
//      has no area constraint; outside that band it has collapsed or blown up);
// and across the runs
//   5. the deformation measure is clearly larger for k = 10: the mean over bodies and output
//      times of the deformation parameter (r_max - r_min)/(r_max + r_min) of the rim radii
//      (solid/body_geometry.hpp) is at least twice that of k = 100.
// usage: cavity_objects_check <cds_radius> <base_k10> <base_k100>
//
// Grid study (`--grid-study`, label slow): the k = 100 scene with sub-markers (marker spacing <= h,
// so that the rims stay closed on the finer grids) on three grids N = 100, 150, 200 with the step
// cap refined with h; per figure the observed order, Richardson value and fine-grid GCI
// (metrics/grid_convergence.hpp, formal order 1 of the immersed boundary), and the shipped scene's
// figure (100 x 100, markers at the rim points) against the Richardson value, as information.
// Gate: the mean deformation parameter converges over the three grids (README.md, "Grid study").
//        cavity_objects_check --grid-study <base_N1> <base_N2> <base_N3> <N1> <N2> <N3> <base_shipped>
// The end time, the area band and the deformation ratio are solver/metrics/case_criteria.hpp's
// (one definition with `ibms compare`).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "verification/common/results_csv.hpp"
#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/csv_reader.hpp"
#include "metrics/grid_convergence.hpp"

using namespace ibms;
using namespace ibms::validation;

namespace {

struct RunFigures {
  double end_time = 0, min_wall = INFINITY, min_rim = INFINITY, max_inside = 0, max_crossings = 0;
  double first_fold = INFINITY;  // first output time at which a rim crosses itself
  double max_self_crossings = 0;  // largest count of crossing edge pairs (all rims) at one output time
  double area_min = INFINITY, area_max = 0, mean_deformation = 0, max_deformation = 0;
};

RunFigures measure(const std::string& base) {
  const SeriesTable s = read_series_csv(base + "_bodies.csv");
  RunFigures f;
  f.end_time = s.at("time").back();
  for (double v : s.at("bodies/min_wall_distance")) f.min_wall = std::min(f.min_wall, v);
  for (double v : s.at("bodies/min_rim_distance")) f.min_rim = std::min(f.min_rim, v);
  for (double v : s.at("bodies/n_points_inside_others")) f.max_inside = std::max(f.max_inside, v);
  for (double v : s.at("bodies/n_edge_crossings")) f.max_crossings = std::max(f.max_crossings, v);
  const auto& time = s.at("time");
  const auto& folds = s.at("bodies/n_self_crossings");
  for (std::size_t k = 0; k < folds.size(); ++k) {
    if (folds[k] > 0 && !std::isfinite(f.first_fold)) f.first_fold = time[k];
    f.max_self_crossings = std::max(f.max_self_crossings, folds[k]);
  }
  double sum = 0;
  long count = 0;
  for (int b = 0;; ++b) {
    char name[32];
    std::snprintf(name, sizeof name, "body_%03d", b);
    if (!s.count(std::string(name) + "/area")) break;
    const auto& area = s.at(std::string(name) + "/area");
    for (double a : area) {
      f.area_min = std::min(f.area_min, a / area.front());
      f.area_max = std::max(f.area_max, a / area.front());
    }
    for (double d : s.at(std::string(name) + "/deformation")) {
      sum += d;
      ++count;
      f.max_deformation = std::max(f.max_deformation, d);
    }
  }
  f.mean_deformation = sum / count;
  return f;
}

int grid_study(char** argv) {
  const std::string name = "cavity_deformable_objects";
  const RunFigures run[3] = {measure(argv[2]), measure(argv[3]), measure(argv[4])};
  const double n[3] = {std::atof(argv[5]), std::atof(argv[6]), std::atof(argv[7])};
  const RunFigures shipped = measure(argv[8]);
  for (const RunFigures& f : run)
    if (f.end_time < criteria::deformable_t_end * (1 - 1e-9))
      throw std::runtime_error("a grid-study run ended at t = " + std::to_string(f.end_time));
  struct Figure {
    const char* label;
    double RunFigures::*member;
  };
  const Figure figures[] = {{"mean deformation parameter", &RunFigures::mean_deformation},
                            {"max deformation parameter", &RunFigures::max_deformation},
                            {"smallest area / A0", &RunFigures::area_min},
                            {"smallest rim distance between bodies", &RunFigures::min_rim},
                            {"smallest rim-point distance to a wall", &RunFigures::min_wall}};
  const std::string grids = " (k = 100, sub-markers, N = " + std::string(argv[5]) + ", " + argv[6] + ", " + argv[7] + ")";
  std::printf("cavity with deformable objects, grid study%s:\n", grids.c_str());
  std::printf("  %-38s %9s %9s %9s  order  Richardson    GCI    shipped 100^2 (no sub-markers)\n", "figure", argv[5],
              argv[6], argv[7]);
  bool mean_converges = false;
  for (const Figure& q : figures) {
    const double f1 = run[0].*q.member, f2 = run[1].*q.member, f3 = run[2].*q.member;
    const GridConvergence g = grid_convergence(1 / n[2], 1 / n[1], 1 / n[0], f3, f2, f1, immersed_boundary_order);
    if (g.converging) {
      const double off = (shipped.*q.member - g.extrapolated) / g.extrapolated;
      std::printf("  %-38s %9.5g %9.5g %9.5g  %5.2f  %10.5g  %5.2f %%  %.5g (%+.2f %% from Richardson)\n", q.label, f1,
                  f2, f3, g.order, g.extrapolated, 100 * g.gci_fine, shipped.*q.member, 100 * off);
    } else {
      // No order, no GCI: the spread of the three grids about the finest, and the shipped figure's
      // distance from the finest.
      const double spread = (std::max({f1, f2, f3}) - std::min({f1, f2, f3})) / std::abs(f3);
      std::printf("  %-38s %9.5g %9.5g %9.5g  %s, spread %.2f %% of the finest  %.5g (%+.2f %% from N = %s)\n",
                  q.label, f1, f2, f3, g.monotone ? "not converging" : "non-monotone", 100 * spread, shipped.*q.member,
                  100 * (shipped.*q.member - f3) / f3, argv[7]);
    }
    if (std::isfinite(g.gci_fine)) {
      record_info(name, std::string("GCI of the finest grid, ") + q.label + grids, g.gci_fine);
      record_info(name, std::string("Richardson value, ") + q.label + grids, g.extrapolated);
    }
    if (q.member == &RunFigures::mean_deformation) mean_converges = g.converging;
  }
  std::printf("%s the mean deformation parameter converges over the three grids\n", mean_converges ? "PASS" : "FAIL");
  record(name, "grid study: mean deformation parameter converges (1 = yes)" + grids, 1.0, mean_converges ? 1.0 : 0.0,
         mean_converges);
  return mean_converges ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 9 && std::string(argv[1]) == "--grid-study") {
    try {
      return grid_study(argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cavity_objects_check: %s\n", e.what());
      return 2;
    }
  }
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <cds_radius> <base_k10> <base_k100>\n", argv[0]);
    return 2;
  }
  try {
    const double end_time = criteria::deformable_t_end;
    const double area_lo = criteria::area_ratio_min, area_hi = criteria::area_ratio_max;
    const double ratio_min = criteria::deformation_ratio_min;
    const double r_c = std::atof(argv[1]);
    const RunFigures k10 = measure(argv[2]), k100 = measure(argv[3]);
    bool all = true;
    const std::string name = "cavity_deformable_objects";
    // The runs under the papers' coupling (k10_papers, k100_papers) record their metrics under a prefix.
    const std::string prefix = std::string(argv[2]).find("_papers") != std::string::npos ? "papers' coupling: " : "";
    for (const auto& [label, f] : {std::pair{"k = 10", k10}, std::pair{"k = 100", k100}}) {
      const bool reached = f.end_time >= end_time * (1 - 1e-9);
      const bool inside_box = f.min_wall >= 0.5 * r_c;
      const bool apart = f.max_inside == 0 && f.max_crossings == 0 && f.min_rim >= r_c;
      const bool bounded = f.area_min >= area_lo && f.area_max <= area_hi;
      std::printf("%s %s: 1. reached t = %.4g (end %.4g)\n", reached ? "PASS" : "FAIL", label, f.end_time, end_time);
      std::printf("%s %s: 2. min rim-point distance to a wall %.4g (>= %.4g)\n", inside_box ? "PASS" : "FAIL", label,
                  f.min_wall, 0.5 * r_c);
      std::printf("%s %s: 3. min rim distance between bodies %.4g (>= %.4g), rim points inside another body %g, "
                  "crossing edges %g\n",
                  apart ? "PASS" : "FAIL", label, f.min_rim, r_c, f.max_inside, f.max_crossings);
      std::printf("%s %s: 4. area / A0 in [%.4f, %.4f] (band [0.5, 1.5])\n", bounded ? "PASS" : "FAIL", label,
                  f.area_min, f.area_max);
      // 3b: the stiffer bodies must stay unfolded; the soft ones' first fold is a measured figure.
      const bool gate_fold = std::string(label) == "k = 100";
      const bool unfolded = !std::isfinite(f.first_fold);
      if (gate_fold)
        std::printf("%s %s: 3b. no rim crosses itself (first fold at t = %g)\n", unfolded ? "PASS" : "FAIL", label,
                    f.first_fold);
      else
        std::printf("     %s: 3b. first time a rim crosses itself: %s\n", label,
                    unfolded ? "none" : std::to_string(f.first_fold).c_str());
      std::printf("     %s: deformation parameter mean %.4f, max %.4f\n", label, f.mean_deformation, f.max_deformation);
      const std::string l = prefix + label;
      record(name, l + ": reached end time (measured: t_end)", end_time, f.end_time, reached);
      record(name, l + ": min rim-point distance to a wall (>= r_c / 2)", 0.5 * r_c, f.min_wall, inside_box);
      record(name, l + ": min rim-point distance between bodies (>= r_c, none inside another, no crossing edges)", r_c,
             f.min_rim, apart);
      record(name, l + ": min area / A0 (>= 0.5)", area_lo, f.area_min, f.area_min >= area_lo);
      record(name, l + ": max area / A0 (<= 1.5)", area_hi, f.area_max, f.area_max <= area_hi);
      if (gate_fold)
        record(name, l + ": no rim crosses itself (measured: crossing edge pairs within rims, largest at one output time)", 0.0,
               f.max_self_crossings, unfolded);
      else if (unfolded)
        record_info(name, l + ": crossing edge pairs within rims, largest at one output time (none: no rim folds)",
                    f.max_self_crossings);
      else
        record_info(name, l + ": first time a rim crosses itself (no self-contact in the model)", f.first_fold);
      record_info(name, l + ": mean deformation parameter", f.mean_deformation);
      record_info(name, l + ": max deformation parameter", f.max_deformation);
      all = all && reached && inside_box && apart && bounded && (!gate_fold || unfolded);
    }
    const double ratio = k10.mean_deformation / k100.mean_deformation;
    const bool softer = ratio >= ratio_min;
    std::printf("%s 5. mean deformation k = 10 / k = 100 = %.3f (>= 2)\n", softer ? "PASS" : "FAIL", ratio);
    record(name, prefix + "mean deformation parameter ratio k=10 / k=100 (>= 2)", ratio_min, ratio, softer);
    return all && softer ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cavity_objects_check: %s\n", e.what());
    return 2;
  }
}
