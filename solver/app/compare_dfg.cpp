// `ibms compare` for the DFG cylinder benchmarks (compare_dfg.hpp). Tolerances are the case checks'
// (validation/dfg_cylinder_2d1/CMakeLists.txt and check.cpp): c_D within 1 % (2D-1); the Strouhal
// number within 1 % and max c_D within 2 % (2D-2), against the published value and against ibms's
// own finest run (reference/ibms_*.csv). A file with a control-volume drag column as well (ibms's
// body_000/cv_drag_coefficient, metrics/control_volume_force.hpp) gets its agreement with the drag
// as information: final values (2D-1), time means over the measured window (2D-2).
#include "app/compare_dfg.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "metrics/csv_reader.hpp"
#include "app/compare_report.hpp"
#include "core/errors.hpp"
#include "metrics/force_metrics.hpp"
#include "metrics/case_criteria.hpp"
#include "metrics/control_volume_force.hpp"

namespace ibms {
namespace {

constexpr double steady_drag_tolerance = criteria::dfg_steady_drag_tolerance;
constexpr double strouhal_tolerance = criteria::dfg_strouhal_tolerance;
constexpr double drag_max_tolerance = criteria::dfg_drag_max_tolerance;
constexpr double periodic_window = 4.0;           // time units at the end of the history
constexpr double diameter = 0.1, mean_speed_2d2 = 1.0;

int column(const CsvTable& t, const std::vector<std::string>& aliases, bool required, const std::string& what) {
  const int c = t.find(aliases);
  if (c < 0 && required)
    throw InputError(t.path + ":" + std::to_string(t.header_line) + ": header needs a column " + what);
  return c;
}

// Delta p per row: a pressure_difference column, or ibms's six probe pressures; empty if neither.
std::vector<double> pressure_difference(const CsvTable& t) {
  const int c = t.find({"pressure_difference", "delta_p", "dp"});
  if (c >= 0) return t.columns[c];
  std::array<int, 6> p{};
  for (int k = 0; k < 6; ++k) {
    p[k] = t.find({fmt::format("probe_{:03d}/pressure", k)});
    if (p[k] < 0) return {};
  }
  std::vector<double> out(t.lines.size());
  for (std::size_t r = 0; r < out.size(); ++r) {
    std::array<double, 6> row{};
    for (int k = 0; k < 6; ++k) row[k] = t.columns[p[k]][r];
    out[r] = dfg_pressure_difference(row);
  }
  return out;
}

const std::vector<std::string> drag_names{"drag_coefficient", "c_d", "cd", "body_000/drag_coefficient"};
const std::vector<std::string> lift_names{"lift_coefficient", "c_l", "cl", "body_000/lift_coefficient"};
const std::vector<std::string> cv_drag_names{"cv_drag_coefficient", "c_d_cv", "body_000/cv_drag_coefficient"};

// The control-volume drag beside the drag, if the file has it (information, not gated).
void cv_drag_info(const DragAgreement& a, const std::string& what) {
  std::printf("  %-62s c_D %.7g, control volume %.7g (%+.2e)   info\n",
              ("control-volume c_D vs c_D, " + what).c_str(), a.immersed_boundary, a.control_volume,
              a.relative_difference);
}

struct SteadyFigures { double drag, lift, dp, cv_drag = NAN; };

SteadyFigures steady_figures(const std::string& path) {
  const CsvTable t = read_csv(path);
  if (t.lines.empty()) throw InputError(path + ": no data rows");
  const int cd = column(t, drag_names, true, "drag_coefficient");
  const int cl = column(t, lift_names, true, "lift_coefficient");
  const std::vector<double> dp = pressure_difference(t);
  const int cv = column(t, cv_drag_names, false, "cv_drag_coefficient");
  return {t.columns[cd].back(), t.columns[cl].back(), dp.empty() ? NAN : dp.back(),
          cv < 0 ? NAN : t.columns[cv].back()};
}

PeriodicForces periodic_figures(const std::string& path, DragAgreement* cv_drag = nullptr,
                                bool* has_cv_drag = nullptr) {
  const CsvTable t = read_csv(path);
  const int ct = column(t, {"time", "t"}, true, "time");
  const int cd = column(t, drag_names, true, "drag_coefficient");
  const int cl = column(t, lift_names, true, "lift_coefficient");
  if (t.lines.size() < 10) throw InputError(path + ": a force history needs at least 10 rows");
  require_increasing(t, ct);
  const std::vector<double>& time = t.columns[ct];
  const int cv = column(t, cv_drag_names, false, "cv_drag_coefficient");
  if (has_cv_drag != nullptr) *has_cv_drag = cv >= 0;
  if (cv >= 0 && cv_drag != nullptr) try {
      *cv_drag = mean_drag_agreement(time, t.columns[cd], t.columns[cv], time.back() - periodic_window);
    } catch (const std::invalid_argument& e) {
      throw InputError(path + ": " + e.what());
    }
  try {
    return periodic_forces(time, t.columns[cd], t.columns[cl], pressure_difference(t), time.back() - periodic_window,
                           diameter, mean_speed_2d2);
  } catch (const std::runtime_error& e) {
    throw InputError(path + ": " + e.what() + " (the last " + fmt::format("{:g}", periodic_window) +
                     " time units are measured)");
  }
}

// A line against ibms's own reference: gated only where that reference lies inside the published
// interval [lower, upper] of the quantity; otherwise shown as information with the reason, so
// that a code matching the literature is not failed for missing ibms's own error.
void own_reference_line(Verdict& verdict, const std::string& what, double measured, double own, double tolerance,
                        const std::string& published_file, const std::string& quantity) {
  const double lower = reference_value(published_file, quantity, "lower");
  const double upper = reference_value(published_file, quantity, "upper");
  if (own >= lower && own <= upper) {
    verdict.line(fmt::format("|{} / {:.6g} (ibms reference) - 1|", what, own), tolerance, std::abs(measured / own - 1));
    return;
  }
  std::printf("  (not gated: ibms's own %s %.6g lies outside the published [%.6g, %.6g])\n", what.c_str(), own, lower,
              upper);
  Verdict::info(what + " against ibms's own reference", measured, own);
}

}  // namespace

int compare_dfg_steady(const std::vector<std::string>& files, const std::string& validation_dir) {
  if (files.size() != 1) throw InputError("dfg_cylinder_2d1: give exactly one CSV file (drag_coefficient, lift_coefficient[, pressure_difference])");
  const std::string dir = validation_dir + "/dfg_cylinder_2d1/reference/";
  const SteadyFigures f = steady_figures(files[0]);
  const SteadyFigures own = steady_figures(dir + "ibms_dfg_2d1.csv");
  const double drag_ref = reference_value(dir + "dfg_2d1.csv", "drag_coefficient");
  std::printf("ibms compare dfg_cylinder_2d1: %s\n", files[0].c_str());
  Verdict::header();
  Verdict verdict;
  verdict.line(fmt::format("|c_D / {:.6g} (John & Matthies 2001) - 1|", drag_ref), steady_drag_tolerance,
               std::abs(f.drag / drag_ref - 1));
  own_reference_line(verdict, "c_D", f.drag, own.drag, steady_drag_tolerance, dir + "dfg_2d1.csv", "drag_coefficient");
  Verdict::info("c_D", f.drag, drag_ref);
  Verdict::info("c_L", f.lift, reference_value(dir + "dfg_2d1.csv", "lift_coefficient"));
  if (!std::isnan(f.dp)) Verdict::info("Delta p", f.dp, reference_value(dir + "dfg_2d1.csv", "pressure_difference"));
  if (!std::isnan(f.cv_drag)) cv_drag_info(final_drag_agreement({f.drag}, {f.cv_drag}), "last row");
  std::printf("dfg_cylinder_2d1: %s\n", verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

int compare_dfg_periodic(const std::vector<std::string>& files, const std::string& validation_dir) {
  if (files.size() != 1) throw InputError("dfg_cylinder_2d2: give exactly one CSV file (time, drag_coefficient, lift_coefficient[, pressure_difference])");
  const std::string dir = validation_dir + "/dfg_cylinder_2d2/reference/";
  DragAgreement cv_drag;
  bool has_cv_drag = false;
  const PeriodicForces f = periodic_figures(files[0], &cv_drag, &has_cv_drag);
  const PeriodicForces own = periodic_figures(dir + "ibms_dfg_2d2_forces.csv");
  const std::string ref = dir + "dfg_2d2.csv";
  const double st_ref = reference_value(ref, "strouhal_number");
  const double cd_ref = reference_value(ref, "drag_coefficient_max");
  std::printf("ibms compare dfg_cylinder_2d2: %s (%d lift periods in the last %g time units)\n", files[0].c_str(),
              f.periods, periodic_window);
  Verdict::header();
  Verdict verdict;
  verdict.line(fmt::format("|St / {:.4g} (Schaefer & Turek 1996) - 1|", st_ref), strouhal_tolerance, std::abs(f.strouhal / st_ref - 1));
  verdict.line(fmt::format("|max c_D / {:.4g} (Schaefer & Turek 1996) - 1|", cd_ref), drag_max_tolerance,
               std::abs(f.drag_max / cd_ref - 1));
  own_reference_line(verdict, "St", f.strouhal, own.strouhal, strouhal_tolerance, ref, "strouhal_number");
  own_reference_line(verdict, "max c_D", f.drag_max, own.drag_max, drag_max_tolerance, ref, "drag_coefficient_max");
  Verdict::info("max c_L", f.lift_max, reference_value(ref, "lift_coefficient_max"));
  if (!std::isnan(f.pressure_difference_half_period))
    Verdict::info("Delta p half a period after max c_L", f.pressure_difference_half_period,
                  reference_value(ref, "pressure_difference_half_period"));
  if (has_cv_drag) cv_drag_info(cv_drag, fmt::format("means over the last {:g} time units", periodic_window));
  std::printf("dfg_cylinder_2d2: %s\n", verdict.pass ? "pass" : "FAIL");
  return verdict.pass ? 0 : 1;
}

}  // namespace ibms
