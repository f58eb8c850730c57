// Work-precision: error against wall time over at least four resolutions for
//   mms            unsteady manufactured solution (verification/fluid/manufactured_solution.hpp) to
//                  t = 1, dt = 0.25 h; error: L2 norm of u - u_exact over the cells;
//   cavity_re100   lid-driven cavity Re 100 (the case's scene) run to a velocity change rate of 1e-6
//                  (run.steady_tolerance, the criterion of the Basilisk comparison);
//   cavity_re1000  the same at Re 1000; error of both: the largest difference of the
//                  centre-line extrema u_min (x = 1/2), v_max and v_min (y = 1/2) from the spectral
//                  values of Botella & Peyret (1998) (validation/<case>/reference/
//                  botella_peyret_extrema.csv), each extremum from the parabola through the discrete
//                  extremum and its two neighbours (the rule of the Basilisk comparison, bench/README.md);
//   settling_disk  the settling disk to t = 0.7 s (past the maximum, before touchdown); error:
//                  |max settling speed / ibms 400 x 1200 reference - 1| (reference/ibms_settling_history.csv);
//   dfg_2d1_<coupling>  DFG 2D-1 (validation/dfg_cylinder_2d1, Re 20, steady) at D/h = 10-40; error:
//                  |final c_D / 5.57954 - 1|, the reference value of John & Matthies (2001) in
//                  reference/dfg_2d1.csv;
//   dfg_2d2_<coupling>  DFG 2D-2 (validation/dfg_cylinder_2d2, Re 100, periodic) to t = 12 at the same
//                  grids; error: |max c_D over t >= 8 / 3.23 - 1|, the midpoint of the bounds 3.22-3.24
//                  of Schaefer & Turek (1996) in reference/dfg_2d2.csv;
//   <coupling>: uhlmann (the papers' direct forcing as the 2D-1 scene ships it) or no_slip (the
//   Lagrange multipliers of the no-slip constraint on the face velocities as the 2D-2 scene ships it).
// Wall time is the whole run (cavity, disk and cylinders through run_simulation, with its output
// writing); the CPU time of the process during the run is printed beside it. Writes
// <out>/work_precision_<case>.csv (N,h,steps,wall_seconds,error; N is D/h for the cylinders) after
// every resolution, with the least-squares slope of log(error) against log(wall time) in a comment
// line, and work_precision_slopes.csv (with a selection: work_precision_<selection>_slopes.csv); then, when a dfg_2d2 case
// ran, from the two dfg_2d2 files in <out>, the wall time at which each coupling reaches 3 % on max
// c_D and their ratio (also in time_to_target_dfg_2d2.csv).
// usage: bench_work_precision [quick|default|full] [out_dir] [case[:N,N...]...] [--set key=value]...
//   a case may name a family (dfg_2d1, dfg_2d2: both couplings); ":N,N" runs only those
//   resolutions and keeps the case file's rows at the others (adds a finer point to an earlier run);
//   --set changes a key of the cavities' scenes (e.g. fluid.convection=quick, run.cfl=0.8), as
//   `ibms run --set` does: one candidate scheme per invocation (docs/fluid-accuracy.md); the keys
//   are written into each case file's header.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/fluid_solver.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"
#include "sim/run/centreline_profiles.hpp"
#include "sim/time_step_limits.hpp"
#include "metrics/force_metrics.hpp"
#include "sim/run/run.hpp"
#include "metrics/profile.hpp"
#include "metrics/grid_convergence.hpp"
#include "metrics/body_series.hpp"
#include "metrics/csv_reader.hpp"
#include "verification/common/manufactured_run.hpp"
#include "verification/fluid/manufactured_solution.hpp"

#include "bench_paths.hpp"

using namespace ibms;
using clock_type = std::chrono::steady_clock;

namespace {

const std::string source_dir = IBMS_SOURCE_DIR;
std::vector<std::string> cavity_sets;  // --set key=value of the command line, for the cavities' scenes
std::string cavity_scheme;             // the fluid scheme of the last cavity run, for its CSV

// One resolution's run: n the case's resolution (cells, or D/h for the cylinders), seconds the
// wall time; cpu_seconds the process's CPU time over the same span, value the measured figure the
// error is taken of, where the case has one, and note a remark on it (printed, not written to the CSV).
struct Point {
  int n;
  double h;
  long steps;
  double seconds;
  double error;
  double cpu_seconds = NAN;
  double value = NAN;
  std::string note;
};

double seconds_since(clock_type::time_point start) {
  return std::chrono::duration<double>(clock_type::now() - start).count();
}

double cpu_seconds_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

// Unsteady MMS to t = 1 with dt = 0.25 h (as the convergence test, the same runner).
Point run_mms(int n) {
  verification::ManufacturedSolution ms;
  ms.steady = false;
  const Grid g(n, n, 1.0, 1.0);
  const double dt = 0.25 / n;
  const auto start = clock_type::now();
  const std::clock_t cpu_start = std::clock();
  FluidSolver solver(g, ms.viscosity, FluidBoundaries{});
  FluidState state = solver.make_state();
  const long steps = verification::run_manufactured(ms, g, solver, state, dt, /*end_time=*/1.0, /*steady_tolerance=*/0.0);
  const double seconds = seconds_since(start), cpu = cpu_seconds_since(cpu_start);
  const double error = verification::manufactured_errors(ms, g, state, dt, /*remove_pressure_mean=*/false).u_l2;
  return {n, 1.0 / n, steps, seconds, error, cpu, NAN, ""};
}

// Cavity case at n^2 to its steady-state criterion; error against Botella & Peyret's extrema.
Point run_cavity(const std::string& case_name, int n, const std::string& work_dir) {
  const std::string dir = source_dir + "/validation/" + case_name;
  // The steady criterion of the Basilisk comparison (bench/reference/basilisk_cavity.csv): 1e-6.
  std::vector<std::string> sets{"domain.cells_x=" + std::to_string(n), "domain.cells_y=" + std::to_string(n),
                                "run.steady_tolerance=1e-6"};
  sets.insert(sets.end(), cavity_sets.begin(), cavity_sets.end());
  Scene scene = read_scene_file(dir + "/scene.toml", sets);
  std::ostringstream scheme;
  scheme << "fluid.convection = " << scene_schema::name_of(scene.fluid.convection)
         << ", fluid.wall_closure = " << scene_schema::name_of(scene.fluid.wall_closure) << ", run.cfl = " << scene.run.cfl;
  cavity_scheme = scheme.str();
  const auto start = clock_type::now();
  const std::clock_t cpu_start = std::clock();
  Simulation sim(scene);
  const RunSummary summary =
      run_simulation(sim, {work_dir + "/" + case_name + "_" + std::to_string(n) + ".h5", /*quiet=*/true});
  const double seconds = seconds_since(start), cpu = cpu_seconds_since(cpu_start);
  const CentrelineProfiles p = centreline_profiles(sim);
  const double worst = largest_extremum_error(
      centreline_extrema(p.y, p.u, p.x, p.v),
      published_extrema(dir + "/reference/botella_peyret_extrema.csv"));
  return {n, 1.0 / n, summary.steps, seconds, worst, cpu, NAN, ""};
}

// Settling disk with n_x cells across the 2 cm width (n_y = 3 n_x, rim spacing ~h) to t = 0.7 s.
Point run_settling(int n_x, const std::string& work_dir) {
  const std::string dir = source_dir + "/validation/settling_disk";
  const int markers = static_cast<int>(std::lround(0.4 * n_x));
  Scene scene = read_scene_file(dir + "/scene.toml",
                                {"domain.cells_x=" + std::to_string(n_x), "domain.cells_y=" + std::to_string(3 * n_x),
                                 "bodies.0.n_surface_points=" + std::to_string(markers), "run.end_time=0.7"});
  const std::string out = work_dir + "/settling_disk_" + std::to_string(n_x) + ".h5";
  const auto start = clock_type::now();
  const std::clock_t cpu_start = std::clock();
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {out, /*quiet=*/true});
  const double seconds = seconds_since(start), cpu = cpu_seconds_since(cpu_start);
  const SeriesTable series = read_series_csv(work_dir + "/settling_disk_" + std::to_string(n_x) + "_bodies.csv");
  const SeriesTable ref = read_series_csv(dir + "/reference/ibms_settling_history.csv");
  const double speed = max_settling_speed(series.at("body_000/velocity_y"));
  const double speed_ref = max_settling_speed(ref.at("v"));
  return {n_x, 2.0 / n_x, summary.steps, seconds, std::abs(speed / speed_ref - 1.0), cpu, speed, ""};
}

// The two immersed-boundary couplings (docs/method.md §3.5, §3.7) as scene overrides.
struct CouplingSettings {
  std::string name;
  std::vector<std::string> overrides;
};

// uhlmann: the papers' direct forcing as the 2D-1 case calibrated it (its README): 3 passes,
// markers retracted by 0.25 h (the Couette calibration), nu dt / h^2 <= 0.2 (its slip grows with
// that number); constrained_velocity is not read under it and is set to its default.
const CouplingSettings uhlmann_coupling{
    "uhlmann", {"ibm.coupling=\"uhlmann\"", "ibm.constrained_velocity=\"cells\"", "ibm.forcing_passes=3",
                "ibm.marker_retraction=0.25", "run.max_viscous_number=0.2"}};
// no_slip: the forces as the Lagrange multipliers of no-slip on the face velocities, as both DFG
// scenes ship it: slip tolerance 1e-4, markers retracted by 0.3 h (the face constraint's effective
// radius, docs/method.md §3.7), no cap on nu dt / h^2, one forcing pass for the first step's guess.
const CouplingSettings no_slip_coupling{
    "no_slip", {"ibm.coupling=\"no_slip\"", "ibm.constrained_velocity=\"faces\"", "ibm.slip_tolerance=1e-4",
                "ibm.forcing_passes=1", "ibm.marker_retraction=0.3", "run.max_viscous_number=0"}};

// The DFG channel at D/h = n: 22 n x round(4.1 n) cells, round(pi n) markers (rim spacing ~h), as
// the cases' CMakeLists.txt set their grids.
std::vector<std::string> dfg_grid(int n) {
  return {"domain.cells_x=" + std::to_string(22 * n), "domain.cells_y=" + std::to_string((41 * n + 5) / 10),
          "bodies.0.n_surface_points=" + std::to_string((314159 * n + 50000) / 100000)};
}

// DFG 2D-1 (Re 20) at D/h = n under `coupling`; error |final c_D / John & Matthies (2001) - 1|.
// uhlmann stops at the steady criterion 1e-3 (the papers' set-up of the case). no_slip runs to
// t = 10 without it, as the scene ships: its marker system's slip floor (2-4e-5 U, docs/method.md
// §3.7) keeps the steady residual above the criterion, and c_D at t = 10 is within 5.4e-5 (D/h = 10) and 3.6e-6 (D/h = 20) of its value at t = 15.
Point run_dfg_2d1(const CouplingSettings& coupling, int n, const std::string& work_dir) {
  const std::string dir = source_dir + "/validation/dfg_cylinder_2d1";
  std::vector<std::string> overrides = dfg_grid(n);
  overrides.insert(overrides.end(), coupling.overrides.begin(), coupling.overrides.end());
  if (coupling.name == "uhlmann") overrides.insert(overrides.end(), {"run.end_time=40", "run.steady_tolerance=1e-3"});
  const Scene scene = read_scene_file(dir + "/scene.toml", overrides);
  const std::string stem = work_dir + "/dfg_2d1_" + coupling.name + "_" + std::to_string(n);
  const auto start = clock_type::now();
  const std::clock_t cpu_start = std::clock();
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {stem + ".h5", /*quiet=*/true});
  const double seconds = seconds_since(start), cpu = cpu_seconds_since(cpu_start);
  const SeriesTable series = read_series_csv(stem + "_bodies.csv");
  const double drag = series_column(series, "body_000/drag_coefficient", stem + "_bodies.csv").back();
  const double reference = reference_value(dir + "/reference/dfg_2d1.csv", "drag_coefficient");
  return {n, 0.1 / n, summary.steps, seconds, std::abs(drag / reference - 1.0), cpu, drag, ""};
}

// DFG 2D-2 (Re 100) at D/h = n under `coupling` to the scene's t = 12; error |max c_D over t >= 8
// (metrics/force_metrics.hpp, as the case's check) / midpoint of Schaefer & Turek's bounds - 1|.
Point run_dfg_2d2(const CouplingSettings& coupling, int n, const std::string& work_dir) {
  const std::string dir = source_dir + "/validation/dfg_cylinder_2d2";
  std::vector<std::string> overrides = dfg_grid(n);
  overrides.insert(overrides.end(), coupling.overrides.begin(), coupling.overrides.end());
  const Scene scene = read_scene_file(dir + "/scene.toml", overrides);
  const std::string stem = work_dir + "/dfg_2d2_" + coupling.name + "_" + std::to_string(n);
  const auto start = clock_type::now();
  const std::clock_t cpu_start = std::clock();
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {stem + ".h5", /*quiet=*/true});
  const double seconds = seconds_since(start), cpu = cpu_seconds_since(cpu_start);
  const std::string file = stem + "_bodies.csv";
  const SeriesTable series = read_series_csv(file);
  const PeriodicForces forces =
      periodic_forces(series_column(series, "time", file), series_column(series, "body_000/drag_coefficient", file),
                      series_column(series, "body_000/lift_coefficient", file), /*pressure_difference=*/{},
                      /*t_from=*/8.0, /*length=*/0.1, /*speed=*/1.0);
  const double reference = reference_value(dir + "/reference/dfg_2d2.csv", "drag_coefficient_max");
  // The run's last steps share the time left to t = 12 (docs/method.md §3.7): the step drops there by
  // 5-35 %, and c_D jumps with it for a few steps under both couplings. The maximum over t in [8, 11.5],
  // which ends before those steps (dt < 2e-3 at D/h >= 10), shows how much of max c_D is that jump.
  const auto& time = series_column(series, "time", file);
  const auto& drag = series_column(series, "body_000/drag_coefficient", file);
  double drag_max_before_end = -HUGE_VAL;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= 8.0 && time[k] <= 11.5) drag_max_before_end = std::max(drag_max_before_end, drag[k]);
  char note[96];
  std::snprintf(note, sizeof note, "max c_D over t in [8, 11.5]: %.7g (%+.2f %%)", drag_max_before_end,
                100 * (drag_max_before_end / reference - 1.0));
  return {n, 0.1 / n, summary.steps, seconds, std::abs(forces.drag_max / reference - 1.0), cpu, forces.drag_max, note};
}

// Least-squares slope of log(error) against log(seconds) over all points (metrics::observed_order,
// GSL's fit, with the wall time in the place of h).
double work_precision_slope(const std::vector<Point>& points) {
  std::vector<double> seconds, errors;
  for (const Point& p : points) {
    seconds.push_back(p.seconds);
    errors.push_back(p.error);
  }
  return observed_order(seconds, errors, 0).order;
}

// Wall time at which the error reaches `target`, interpolated in log-log between the first two
// consecutive points that bracket it; the first point's time when it is already there (an upper
// bound, *at_coarsest set); NaN when no point reaches it.
double seconds_to_reach(const std::vector<Point>& points, double target, bool* at_coarsest = nullptr) {
  if (at_coarsest) *at_coarsest = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (points[k].error > target) continue;
    if (k == 0) {
      if (at_coarsest) *at_coarsest = true;
      return points[0].seconds;
    }
    const Point& a = points[k - 1];
    const Point& b = points[k];
    const double w = std::log(target / a.error) / std::log(b.error / a.error);
    return std::exp(std::log(a.seconds) + w * std::log(b.seconds / a.seconds));
  }
  return NAN;
}

// seconds_to_reach as text: "12.3 s", "<= 4.5 s (coarsest run already)" or "not reached (smallest
// error ...)".
std::string time_to_reach(const std::vector<Point>& points, double target) {
  bool at_coarsest = false;
  const double seconds = seconds_to_reach(points, target, &at_coarsest);
  char text[96];
  if (at_coarsest) {
    std::snprintf(text, sizeof text, "<= %.3g s (coarsest run already)", seconds);
  } else if (std::isnan(seconds)) {
    double best = HUGE_VAL;
    for (const Point& p : points) best = std::min(best, p.error);
    std::snprintf(text, sizeof text, "not reached (smallest error %.3g)", best);
  } else {
    std::snprintf(text, sizeof text, "%.3g s", seconds);
  }
  return text;
}

// The rows of a work_precision_<case>.csv (missing file: none), sorted by N.
std::vector<Point> read_points(const std::string& path) {
  std::vector<Point> points;
  if (!std::filesystem::exists(path)) return points;
  const CsvTable t = read_csv(path);
  for (std::size_t k = 0; k < t.rows(); ++k)
    points.push_back({static_cast<int>(std::lround(t.column("n")[k])), t.column("h")[k],
                      std::lround(t.column("steps")[k]), t.column("wall_seconds")[k], t.column("error")[k], NAN, NAN, ""});
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.n < b.n; });
  return points;
}

// The wall time to reach `target` along a curve, with how the true time relates to it: "=" (bracketed,
// interpolated), "<=" (the coarsest run is already there) or ">" (not reached: the longest run).
struct TimeToTarget {
  double seconds;
  std::string relation;
  double smallest_error;
};

TimeToTarget time_to_target(const std::vector<Point>& points, double target) {
  bool at_coarsest = false;
  double seconds = seconds_to_reach(points, target, &at_coarsest);
  double smallest = HUGE_VAL, longest = 0.0;
  for (const Point& p : points) {
    smallest = std::min(smallest, p.error);
    longest = std::max(longest, p.seconds);
  }
  if (std::isnan(seconds)) return {longest, ">", smallest};
  return {seconds, at_coarsest ? "<=" : "=", smallest};
}

// The target of the no-slip coupling on DFG 2D-2: the wall time to 3 % on max c_D under each
// coupling, from <out>/work_precision_dfg_2d2_{uhlmann,no_slip}.csv (this or earlier invocations),
// and the ratio uhlmann / no_slip (a bound when a curve does not bracket 3 %); printed and written
// to <out>/time_to_target_dfg_2d2.csv for the report.
void compare_dfg_2d2_couplings(const std::string& out_dir) {
  const std::vector<Point> papers = read_points(out_dir + "/work_precision_dfg_2d2_uhlmann.csv");
  const std::vector<Point> no_slip = read_points(out_dir + "/work_precision_dfg_2d2_no_slip.csv");
  if (papers.empty() || no_slip.empty()) return;
  const double target = 0.03;
  const TimeToTarget u = time_to_target(papers, target), f = time_to_target(no_slip, target);
  // ratio = t_u / t_f: a lower bound when t_u is one (">") or t_f an upper one ("<="), and so on.
  std::string relation = "undefined";
  if (u.relation == "=" && f.relation == "=") relation = "=";
  else if ((u.relation == "=" || u.relation == ">") && (f.relation == "=" || f.relation == "<=")) relation = ">";
  else if (u.relation == "<=" && f.relation == "=") relation = "<=";
  const double ratio = u.seconds / f.seconds;
  std::printf("dfg_2d2: wall time to %.0f %% on max c_D (log-log interpolation along each curve)\n", 100 * target);
  std::printf("  uhlmann: %s\n  no_slip: %s\n", time_to_reach(papers, target).c_str(), time_to_reach(no_slip, target).c_str());
  std::printf("  ratio uhlmann / no_slip: %s %.3g%s\n", relation.c_str(), ratio,
              u.relation == ">" ? " (uhlmann's longest run over no_slip's time to the target)" : "");
  std::ofstream csv(out_dir + "/time_to_target_dfg_2d2.csv");
  csv << "# bench_work_precision: wall time at which max c_D of DFG 2D-2 comes within " << 100 * target
      << " % of 3.23 (log-log interpolation between the two runs that bracket it), per coupling, and their ratio;\n"
      << "# relation: how the true figure relates to `seconds` (=, <= the coarsest run already there, > not reached"
      << " by the longest run)\n";
  csv << "what,target,seconds,relation,smallest_error\n";
  csv << "uhlmann," << target << "," << u.seconds << "," << u.relation << "," << u.smallest_error << "\n";
  csv << "no_slip," << target << "," << f.seconds << "," << f.relation << "," << f.smallest_error << "\n";
  csv << "ratio," << target << "," << ratio << "," << relation << ",\n";
}

struct Case {
  std::string name, error_definition;
  std::vector<int> quick, standard, full;  // resolutions per level (full: empty = standard)
  std::function<Point(int, const std::string&)> run;
  std::string family;  // a selection naming it runs the case too (dfg_2d1: both couplings)
};

// A selection on the command line: "case" or "case:N,N,...", the resolutions to run (empty: the level's).
struct Selection {
  std::string name;
  std::vector<int> resolutions;
};

Selection parse_selection(const std::string& arg) {
  const auto colon = arg.find(':');
  Selection out{arg.substr(0, colon), {}};
  if (colon == std::string::npos) return out;
  std::stringstream list(arg.substr(colon + 1));
  std::string item;
  while (std::getline(list, item, ','))
    if (!item.empty()) out.resolutions.push_back(std::stoi(item));
  if (out.resolutions.empty()) throw std::runtime_error("no resolution after ':' in '" + arg + "'");
  return out;
}

// Basilisk's recorded points of the cavity at Reynolds number `re` (bench/reference/basilisk_cavity.csv,
// one core of this machine) against this run: ibms's time to Basilisk's error (seconds_to_reach, wall
// time) over Basilisk's time.
void print_basilisk_ratios(int re, const std::vector<Point>& points) {
  const CsvTable basilisk = read_csv(source_dir + "/bench/reference/basilisk_cavity.csv");
  for (std::size_t k = 0; k < basilisk.rows(); ++k) {
    if (std::lround(basilisk.column("re")[k]) != re) continue;
    const double n = basilisk.column("n")[k], seconds = basilisk.column("seconds")[k];
    const double error = basilisk.column("error")[k];
    bool at_coarsest = false;
    const double ibms = seconds_to_reach(points, error, &at_coarsest);
    if (std::isnan(ibms))
      std::printf("  Basilisk %.0f^2: error %.3g in %.3g s; ibms: %s\n", n, error, seconds,
                  time_to_reach(points, error).c_str());
    else
      std::printf("  Basilisk %.0f^2: error %.3g in %.3g s; ibms %s%.3g s: ratio %s%.2f\n", n, error, seconds,
                  at_coarsest ? "<= " : "", ibms, at_coarsest ? "<= " : "", ibms / seconds);
  }
}

// work_precision_<case>.csv: `points` (every row of this invocation and, when kept, rows of an
// earlier one) with the slope over all of them.
void write_case_csv(const std::string& path, const Case& c, const std::string& level, const std::vector<Point>& points,
                    const std::set<int>& kept) {
  const double slope = points.size() >= 2 ? work_precision_slope(points) : NAN;
  std::ofstream csv(path);
  csv << "# bench_work_precision " << c.name << " (level " << level << "): error = " << c.error_definition << "\n";
  if (c.name.rfind("cavity", 0) == 0 && !cavity_scheme.empty()) csv << "# fluid scheme: " << cavity_scheme << "\n";
  if (c.name.rfind("cavity", 0) == 0 && !cavity_sets.empty()) {
    csv << "# scene keys set:";
    for (const std::string& kv : cavity_sets) csv << " " << kv;
    csv << "\n";
  }
  csv << "# least-squares slope of log(error) against log(wall_seconds) over all rows: " << slope << "\n";
  if (!kept.empty()) {
    csv << "# rows kept from an earlier invocation: N =";
    for (int n : kept) csv << " " << n;
    csv << "\n";
  }
  csv << "N,h,steps,wall_seconds,error\n";
  for (const Point& p : points) csv << p.n << "," << p.h << "," << p.steps << "," << p.seconds << "," << p.error << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::string level = argc > 1 ? argv[1] : "default";
  const std::string out_dir = argc > 2 ? argv[2] : IBMS_BENCH_OUTPUT_DIR;
  if (level != "quick" && level != "default" && level != "full") {
    std::fprintf(stderr, "usage: %s [quick|default|full] [out_dir] [case[:N,N...]...]   (full: default + 192^2, "
                 "256^2 for the Re 1000 cavity, D/h = 40 for the cylinders)\n", argv[0]);
    return 2;
  }
  std::vector<Selection> only;
  for (int a = 3; a < argc; ++a) {
    if (std::string(argv[a]) == "--set") {
      if (a + 1 == argc) {
        std::fprintf(stderr, "--set needs key=value\n");
        return 2;
      }
      cavity_sets.push_back(argv[++a]);
      continue;
    }
    only.push_back(parse_selection(argv[a]));
  }
  const std::string work_dir = out_dir + "/work_precision_runs";
  std::filesystem::create_directories(work_dir);
  const std::string dfg_2d1_error =
      "|final c_D / 5.57954 - 1| (DFG 2D-1, John & Matthies 2001; N = D/h)";
  const std::string dfg_2d2_error =
      "|max c_D over t in [8, 12] / 3.23 - 1| (DFG 2D-2, midpoint of Schaefer & Turek 1996's 3.22-3.24; N = D/h)";
  std::vector<Case> cases{
      {"mms", "L2 norm of u - u_exact at t = 1 (unsteady manufactured solution, dt = 0.25 h)",
       {16, 32, 64, 128}, {16, 32, 64, 128, 256}, {}, [](int n, const std::string&) { return run_mms(n); }, ""},
      {"cavity_re100", "max |centre-line extremum - Botella & Peyret (1998)| over u_min, v_max, v_min, steady state",
       {16, 32, 48, 64}, {16, 32, 64, 96, 128}, {},
       [](int n, const std::string& w) { return run_cavity("lid_driven_cavity_re100", n, w); }, ""},
      {"cavity_re1000", "max |centre-line extremum - Botella & Peyret (1998)| over u_min, v_max, v_min, steady state",
       {32, 48, 64, 80}, {32, 48, 64, 96, 128}, {32, 48, 64, 96, 128, 192, 256},
       [](int n, const std::string& w) { return run_cavity("lid_driven_cavity_re1000", n, w); }, ""},
      {"settling_disk", "|max settling speed / ibms 400x1200 reference - 1| (run to t = 0.7 s)",
       {40, 50, 60, 75}, {50, 75, 100, 150}, {}, run_settling, ""}};
  // The cylinders, D/h = 10 and 20 (full: 30 and 40). The D/h = 30 runs of 2D-2 under both couplings
  // took 546 s of the default level's 870 s of this bench, which holds the machine alone; a D/h = 40
  // run of 2D-2 takes 20-45 CPU minutes.
  for (const CouplingSettings* coupling : {&uhlmann_coupling, &no_slip_coupling}) {
    const CouplingSettings& k = *coupling;
    cases.push_back({"dfg_2d1_" + k.name, dfg_2d1_error + ", coupling " + k.name, {10, 20}, {10, 20},
                     {10, 20, 30, 40}, [&k](int n, const std::string& w) { return run_dfg_2d1(k, n, w); }, "dfg_2d1"});
    cases.push_back({"dfg_2d2_" + k.name, dfg_2d2_error + ", coupling " + k.name, {10, 20}, {10, 20},
                     {10, 20, 30, 40}, [&k](int n, const std::string& w) { return run_dfg_2d2(k, n, w); }, "dfg_2d2"});
  }
  for (const Selection& sel : only)
    if (std::none_of(cases.begin(), cases.end(), [&](const Case& c) { return c.name == sel.name || c.family == sel.name; })) {
      std::fprintf(stderr, "unknown case '%s'\n", sel.name.c_str());
      return 2;
    }
  // One slopes file per selection (the workflow runs the cylinders and the other cases as two jobs
  // into one folder, possibly at once): work_precision_slopes.csv for all cases, else
  // work_precision_<selection>_slopes.csv.
  std::string selection_tag;
  for (const Selection& sel : only) selection_tag += sel.name + "_";
  std::ofstream slopes(out_dir + "/work_precision_" + selection_tag + "slopes.csv");
  slopes << "case,slope,n_points,error\n";
  bool ran_dfg_2d2 = false;
  for (const Case& c : cases) {
    const auto sel = std::find_if(only.begin(), only.end(),
                                  [&](const Selection& s) { return s.name == c.name || (!c.family.empty() && s.name == c.family); });
    if (!only.empty() && sel == only.end()) continue;
    std::vector<int> levels = level == "quick" ? c.quick : level == "full" && !c.full.empty() ? c.full : c.standard;
    const std::string csv_path = out_dir + "/work_precision_" + c.name + ".csv";
    // Rows of an earlier invocation at the resolutions not run now (only with a ":N,N" selection).
    std::vector<Point> points;
    std::set<int> kept;
    if (sel != only.end() && !sel->resolutions.empty()) {
      levels = sel->resolutions;
      for (const Point& p : read_points(csv_path))
        if (std::find(levels.begin(), levels.end(), p.n) == levels.end()) {
          points.push_back(p);
          kept.insert(p.n);
        }
    }
    std::printf("%s: %s\n  %6s %10s %8s %12s %12s %12s %12s\n", c.name.c_str(), c.error_definition.c_str(), "N", "h",
                "steps", "wall [s]", "cpu [s]", "value", "error");
    for (const Point& p : points)
      std::printf("  %6d %10.4g %8ld %12.4g %12s %12s %12.4e  (kept)\n", p.n, p.h, p.steps, p.seconds, "", "", p.error);
    for (int n : levels) {
      points.push_back(c.run(n, work_dir));
      const Point p = points.back();
      char value[32] = "-";  // the cases without one figure (mms, cavities) print none
      if (!std::isnan(p.value)) std::snprintf(value, sizeof value, "%.7g", p.value);
      std::printf("  %6d %10.4g %8ld %12.4g %12.4g %12s %12.4e%s%s\n", p.n, p.h, p.steps, p.seconds, p.cpu_seconds, value,
                  p.error, p.note.empty() ? "" : "  ", p.note.c_str());
      std::fflush(stdout);
      std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.n < b.n; });
      write_case_csv(csv_path, c, level, points, kept);  // after every run: a long run stopped keeps the rest
    }
    const double slope = points.size() >= 2 ? work_precision_slope(points) : NAN;  // one row has none
    std::printf("  slope d log(error) / d log(wall time) = %.3f\n", slope);
    // The marks of the Basilisk comparison (bench/README.md, "The mark to beat").
    const std::vector<double> marks = c.name == "cavity_re1000"  ? std::vector<double>{1e-2, 3e-3, 1e-3}
                                      : c.name == "cavity_re100" ? std::vector<double>{5e-4, 2e-4}
                                                                 : std::vector<double>{};
    for (double target : marks)
      std::printf("  time to error %.0e: %s\n", target, time_to_reach(points, target).c_str());
    if (!marks.empty()) print_basilisk_ratios(c.name == "cavity_re1000" ? 1000 : 100, points);
    slopes << c.name << "," << slope << "," << points.size() << ",\"" << c.error_definition << "\"\n";
    ran_dfg_2d2 = ran_dfg_2d2 || c.family == "dfg_2d2";
  }
  if (ran_dfg_2d2) compare_dfg_2d2_couplings(out_dir);
  return 0;
}
