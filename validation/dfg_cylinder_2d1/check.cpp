// Check of the DFG cylinder benchmarks (README.md of dfg_cylinder_2d1 and dfg_cylinder_2d2) from
// the <base>_bodies.csv series that `ibms run` writes (body_000 drag/lift coefficients, the front
// and back probes). For each grid it prints the quantities; over the grids (coarse to fine, at least
// three for a convergence statement) the observed order and the Richardson value by the procedure of
// Celik et al. (2008, J. Fluids Eng. 130, 078001: non-uniform refinement ratios) and the GCI of the
// finest grid; then it checks the targets (README.md) and writes one line per figure to
// $IBMS_VALIDATION_RESULTS.
//
// usage: dfg_check steady   <case> <reference.csv> <gates> <cells_per_diameter>:<base> ...
//        dfg_check periodic <case> <reference.csv> <gates> <t_from> <cells_per_diameter>:<base> ...
// <gates>: comma-separated targets checked (pass/FAIL, exit 1 on a FAIL); every other figure is
// reported as information. drag_finest: c_D at the finest grid within 1 % (2D-1); drag_every: c_D
// on every grid within 1 % (2D-1);
// drag_bounds: c_D on every grid inside the published bounds of the reference file (2D-1: the
// source's own terms, stricter than drag_every's 1 %); drag_richardson: the Richardson c_D within
// 0.5 % (2D-1, three grids); strouhal: St at the finest
// grid within 1 %; drag_max: max c_D at the finest grid within 2 % (2D-2); cv_drag: on every grid,
// the control-volume c_D (body_000/cv_drag_coefficient, metrics/control_volume_force.hpp) within 1 %
// of the immersed-boundary c_D, final values (steady) or time means over t >= t_from (periodic).
// The CMake files say which gate runs at which label and why.
// steady (2D-1): the last row's c_D, c_L and Delta p (probes: ibms::dfg_pressure_difference).
// periodic (2D-2): over t >= t_from, the figures of ibms::periodic_forces (solver/metrics/force_metrics.hpp,
//   shared with `ibms compare`); the reference of 2D-2 is the midpoint of the published bounds.
// Every other figure is reported (info) with its deviation from the reference and whether it lies
// within the published bounds.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/body_series.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/control_volume_force.hpp"
#include "metrics/csv_reader.hpp"
#include "metrics/grid_convergence.hpp"
#include "core/errors.hpp"
#include "metrics/force_metrics.hpp"
#include "verification/common/results_csv.hpp"

using namespace ibms::validation;
using namespace ibms;

namespace {

struct Reference { double value, lower, upper; };

// quantity,value,lower,upper,units through the one CSV reader (a non-numeric bound is an error).
std::map<std::string, Reference> read_reference(const std::string& path) {
  const CsvTable t = read_csv(path, {{"quantity", "units"}});
  const int q = t.find({"quantity"});
  if (q < 0) throw InputError(t.where() + "expected the columns quantity,value,lower,upper");
  const std::vector<double>&value = t.column("value"), &lower = t.column("lower"), &upper = t.column("upper");
  std::map<std::string, Reference> out;
  for (std::size_t k = 0; k < t.rows(); ++k) out[t.text[static_cast<std::size_t>(q)][k]] = {value[k], lower[k], upper[k]};
  return out;
}

const std::vector<double>& column(const SeriesTable& t, const std::string& name, const std::string& file) {
  return series_column(t, name, file);
}

struct GridRun { double resolution; std::string base; };  // one grid's run

// A gate is either |deviation| <= tolerance (is_check) or the figure inside the published bounds
// (bounds_check, recorded without a tolerance: the report states the bounds).
bool report(const std::string& name, const std::string& label, double measured, const Reference& ref,
            double tolerance, bool is_check, bool bounds_check = false) {
  const double deviation = measured / ref.value - 1.0;
  const bool in_bounds = measured >= ref.lower && measured <= ref.upper;
  const bool pass = bounds_check ? in_bounds : std::abs(deviation) <= tolerance;
  std::printf("  %-44s %12.6g  reference %.6g (%+.2f %%), published bounds [%g, %g]: %s%s\n", label.c_str(), measured,
              ref.value, 100 * deviation, ref.lower, ref.upper, in_bounds ? "inside" : "outside",
              is_check || bounds_check ? (pass ? "  -> pass" : "  -> FAIL") : "");
  if (is_check || bounds_check) {
    // The signed deviation (a tolerance gate is on its size): the report judges it on the published bounds.
    record(name, label + " relative to the reference", bounds_check ? NAN : tolerance, deviation, pass);
    return pass;
  }
  record_info(name, label + " relative deviation from the reference", deviation);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 5) throw std::runtime_error("usage: see the header of check.cpp");
    const std::string mode = argv[1], name = argv[2], reference_path = argv[3];
    const auto ref = read_reference(reference_path);
    std::set<std::string> gates;  // every named gate must be known: a misspelt one would check nothing
    {
      std::stringstream list(argv[4]);
      std::string g;
      while (std::getline(list, g, ',')) {
        if (!g.empty() && g != "drag_finest" && g != "drag_every" && g != "drag_bounds" && g != "drag_richardson" && g != "strouhal" && g != "drag_max" &&
            g != "cv_drag" && g != "none")
          throw std::runtime_error("unknown gate '" + g + "'");
        gates.insert(g);
      }
    }
    const auto gated = [&](const char* g) { return gates.count(g) > 0; };
    int first_grid = 5;
    double t_from = 0.0;
    if (mode == "periodic") t_from = std::atof(argv[first_grid++]);
    else if (mode != "steady") throw std::runtime_error("mode must be steady or periodic");
    std::vector<GridRun> grids;
    for (int a = first_grid; a < argc; ++a) {
      const std::string arg = argv[a];
      const auto colon = arg.find(':');
      if (colon == std::string::npos) throw std::runtime_error("expected <cells_per_diameter>:<base>, got " + arg);
      grids.push_back({std::atof(arg.substr(0, colon).c_str()), arg.substr(colon + 1)});
    }
    std::sort(grids.begin(), grids.end(), [](const GridRun& a, const GridRun& b) { return a.resolution < b.resolution; });
    if (gated("drag_richardson") && grids.size() < 3) throw std::runtime_error("the drag_richardson gate needs three grids");
    const double d = 0.1, u_mean = mode == "steady" ? 0.2 : 1.0;
    // Per grid: the figures, in the order of `keys`.
    std::vector<std::string> keys = mode == "steady"
        ? std::vector<std::string>{"drag_coefficient", "lift_coefficient", "pressure_difference"}
        : std::vector<std::string>{"drag_coefficient_max", "lift_coefficient_max", "strouhal_number",
                                   "pressure_difference_half_period"};
    std::vector<std::vector<double>> figures;
    std::vector<DragAgreement> cv_drag;  // per grid: the control-volume c_D beside the IB c_D
    std::vector<double> cv_drag_max_difference;  // periodic: largest |cv - ib| / mean ib of a step in the window
    for (const GridRun& g : grids) {
      const std::string file = g.base + "_bodies.csv";
      const SeriesTable t = read_series_csv(file);
      {
        const auto& ib = column(t, "body_000/drag_coefficient", file);
        const auto& cv = column(t, "body_000/cv_drag_coefficient", file);
        if (mode == "steady") {
          cv_drag.push_back(final_drag_agreement(ib, cv));
        } else {
          const auto& time = column(t, "time", file);
          cv_drag.push_back(mean_drag_agreement(time, ib, cv, t_from));
          double worst = 0.0;
          for (std::size_t r = 0; r < time.size(); ++r)
            if (time[r] >= t_from) worst = std::max(worst, std::abs(cv[r] - ib[r]) / std::abs(cv_drag.back().immersed_boundary));
          cv_drag_max_difference.push_back(worst);
        }
      }
      if (mode == "steady") {
        const double cd = column(t, "body_000/drag_coefficient", file).back();
        const double cl = column(t, "body_000/lift_coefficient", file).back();
        std::array<double, 6> p{};
        for (int k = 0; k < 6; ++k) p[k] = column(t, "probe_00" + std::to_string(k) + "/pressure", file).back();
        const double dp = ibms::dfg_pressure_difference(p);
        figures.push_back({cd, cl, dp});
      } else {
        const auto& time = column(t, "time", file);
        std::vector<double> dp(time.size());
        for (std::size_t r = 0; r < time.size(); ++r) {
          std::array<double, 6> p{};
          for (int k = 0; k < 6; ++k) p[k] = column(t, "probe_00" + std::to_string(k) + "/pressure", file)[r];
          dp[r] = ibms::dfg_pressure_difference(p);
        }
        const PeriodicForces f = periodic_forces(time, column(t, "body_000/drag_coefficient", file),
                                                 column(t, "body_000/lift_coefficient", file), dp, t_from, d, u_mean);
        std::printf("D/h = %g: %d shedding periods after t = %g (every step)\n", g.resolution, f.periods, t_from);
        figures.push_back({f.drag_max, f.lift_max, f.strouhal, f.pressure_difference_half_period});
      }
    }
    bool ok = true;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      std::printf("%s, D/h = %g:\n", name.c_str(), grids[g].resolution);
      for (std::size_t q = 0; q < keys.size(); ++q) {
        const std::string label = keys[q] + " at D/h = " + std::to_string(static_cast<int>(std::lround(grids[g].resolution)));
        const bool finest = g + 1 == grids.size();
        bool check = false;
        double tolerance = NAN;
        if (((finest && gated("drag_finest")) || gated("drag_every")) && mode == "steady" && keys[q] == "drag_coefficient") { check = true; tolerance = criteria::dfg_steady_drag_tolerance; }
        if (finest && mode == "periodic" && keys[q] == "strouhal_number" && gated("strouhal")) { check = true; tolerance = criteria::dfg_strouhal_tolerance; }
        if (finest && mode == "periodic" && keys[q] == "drag_coefficient_max" && gated("drag_max")) { check = true; tolerance = criteria::dfg_drag_max_tolerance; }
        const bool bounds = gated("drag_bounds") && mode == "steady" && keys[q] == "drag_coefficient";
        ok = report(name, label, figures[g][q], ref.at(keys[q]), tolerance, check && !bounds, bounds) && ok;
      }
    }
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const DragAgreement& a = cv_drag[g];
      const double difference = std::abs(a.relative_difference);
      const bool check = gated("cv_drag");
      const bool pass = difference <= criteria::dfg_cv_drag_agreement_tolerance;
      char window[48];
      std::snprintf(window, sizeof window, "mean c_D over t >= %g", t_from);
      const std::string what = mode == "steady" ? "final c_D" : window;
      const std::string label = "control-volume " + what + " vs immersed boundary at D/h = " +
                                std::to_string(static_cast<int>(std::lround(grids[g].resolution)));
      std::printf("  %-72s %.7g vs %.7g (%+.2e)%s\n", label.c_str(), a.control_volume, a.immersed_boundary,
                  a.relative_difference, check ? (pass ? "  -> pass" : "  -> FAIL") : "");
      if (check) {
        record(name, label + ", relative difference", criteria::dfg_cv_drag_agreement_tolerance, difference, pass);
        ok = ok && pass;
      } else {
        record_info(name, label + ", relative difference", a.relative_difference);
      }
      if (!cv_drag_max_difference.empty()) {
        std::printf("  %-72s %.2e\n", "  largest |cv - ib| of a step (every step) over the mean c_D", cv_drag_max_difference[g]);
        record_info(name, "largest |control-volume - immersed-boundary c_D| of a step over the mean c_D at D/h = " +
                              std::to_string(static_cast<int>(std::lround(grids[g].resolution))),
                    cv_drag_max_difference[g]);
      }
    }
    if (grids.size() >= 3) {
      const std::size_t n = grids.size();
      const double h1 = d / grids[n - 1].resolution, h2 = d / grids[n - 2].resolution, h3 = d / grids[n - 3].resolution;
      std::printf("%s, finest three grids (D/h = %g, %g, %g): observed order, Richardson value, GCI of the finest\n",
                  name.c_str(), grids[n - 3].resolution, grids[n - 2].resolution, grids[n - 1].resolution);
      for (std::size_t q = 0; q < keys.size(); ++q) {
        const GridConvergence r = grid_convergence(h1, h2, h3, figures[n - 1][q], figures[n - 2][q], figures[n - 3][q],
                                                   immersed_boundary_order);
        std::printf("  %-36s order %6.3f  Richardson %.6g  GCI %.3g %%\n", keys[q].c_str(), r.order, r.extrapolated,
                    100 * r.gci_fine);
        record_info(name, keys[q] + ": observed order (finest three grids)", r.order);
        record_info(name, keys[q] + ": GCI of the finest grid", r.gci_fine);
        const bool check = mode == "steady" && keys[q] == "drag_coefficient" && gated("drag_richardson");
        if (std::isnan(r.extrapolated)) {
          std::printf("  %s: no Richardson value (the differences change sign or do not shrink)\n", keys[q].c_str());
          if (check) { record(name, keys[q] + " Richardson value relative to the reference", criteria::dfg_richardson_drag_tolerance, NAN, false); ok = false; }
          continue;
        }
        ok = report(name, keys[q] + " Richardson value", r.extrapolated, ref.at(keys[q]),
                    check ? criteria::dfg_richardson_drag_tolerance : NAN, check) && ok;
      }
    }
    std::printf("%s: %s\n", name.c_str(), ok ? "pass" : "FAIL");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dfg_check: %s\n", e.what());
    return 2;
  }
}
