// Work-precision: error against wall time over at least four resolutions for
//   mms            unsteady manufactured solution (verification/fluid/manufactured_solution.hpp) to
//                  t = 1, dt = 0.25 h; error: L2 norm of u - u_exact over the cells;
//   cavity_re100   lid-driven cavity Re 100 run to its steady-state criterion (the case's scene);
//   cavity_re1000  the same at Re 1000; error of both: the largest difference of the
//                  centre-line extrema u_min (x = 1/2), v_max and v_min (y = 1/2) from the spectral
//                  values of Botella & Peyret (1998) (validation/<case>/reference/
//                  botella_peyret_extrema.csv), each extremum from the parabola through the discrete
//                  extremum and its two neighbours (the rule of the Basilisk comparison);
//   settling_disk  the settling disk to t = 0.7 s (past the maximum, before touchdown); error:
//                  |max settling speed / ibms 400 x 1200 reference - 1| (reference/ibms_settling_history.csv).
// Wall time is the whole run (cavity and disk through run_simulation, with its output writing).
// Writes <out>/work_precision_<case>.csv (N,h,steps,wall_seconds,error) with the least-squares
// slope of log(error) against log(wall time) in a comment line, and work_precision_slopes.csv.
// usage: bench_work_precision [quick|default] [out_dir] [case...]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/fluid_solver.hpp"
#include "scene/scene_reader.hpp"
#include "sim/diagnostics.hpp"
#include "sim/run.hpp"
#include "metrics/profile.hpp"
#include "metrics/grid_convergence.hpp"
#include "metrics/body_series.hpp"
#include "metrics/csv_reader.hpp"
#include "verification/fluid/manufactured_solution.hpp"

#include "bench_paths.hpp"

using namespace ibms;
using clock_type = std::chrono::steady_clock;

namespace {

const std::string source_dir = IBMS_SOURCE_DIR;

struct Point { int n; double h; long steps; double seconds; double error; };

double seconds_since(clock_type::time_point start) {
  return std::chrono::duration<double>(clock_type::now() - start).count();
}

// Unsteady MMS to t = 1 with dt = 0.25 h (as the convergence test), forcing at t^{n+1/2}.
Point run_mms(int n) {
  verification::ManufacturedSolution ms;
  ms.steady = false;
  const Grid g(n, n, 1.0, 1.0);
  const double dt = 0.25 / n;
  const auto start = clock_type::now();
  FluidSolver solver(g, ms.viscosity, FluidBoundaries{});
  FluidState state = solver.make_state();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      state.velocity_x(i, j) = ms.u(g.x_centre(i), g.y_centre(j), 0.0);
      state.velocity_y(i, j) = ms.v(g.x_centre(i), g.y_centre(j), 0.0);
      state.pressure(i, j) = ms.p(g.x_centre(i), g.y_centre(j), -0.5 * dt);
    }
  solver.initialise_faces(state);
  CellField fx(g), fy(g);
  const long n_steps = std::lround(1.0 / dt);
  for (long s = 0; s < n_steps; ++s) {
    const double t_half = state.time + 0.5 * dt;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        fx(i, j) = ms.force_x(g.x_centre(i), g.y_centre(j), t_half);
        fy(i, j) = ms.force_y(g.x_centre(i), g.y_centre(j), t_half);
      }
    solver.predict_momentum(state, dt, &fx, &fy);
    solver.project_smac(state, dt);
  }
  const double seconds = seconds_since(start);
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double e = state.velocity_x(i, j) - ms.u(g.x_centre(i), g.y_centre(j), state.time);
      sum += e * e;
    }
  return {n, 1.0 / n, n_steps, seconds, std::sqrt(sum / (n * n))};
}

// Cavity case at n^2 to its steady-state criterion; error against Botella & Peyret's extrema.
Point run_cavity(const std::string& case_name, int n, const std::string& work_dir) {
  const std::string dir = source_dir + "/validation/" + case_name;
  Scene scene = read_scene_file(dir + "/scene.toml",
                                {"domain.cells_x=" + std::to_string(n), "domain.cells_y=" + std::to_string(n)});
  const auto start = clock_type::now();
  Simulation sim(scene);
  const RunSummary summary =
      run_simulation(sim, {work_dir + "/" + case_name + "_" + std::to_string(n) + ".h5", /*quiet=*/true});
  const double seconds = seconds_since(start);
  const CentrelineProfiles p = centreline_profiles(sim);
  const double worst = largest_extremum_error(
      centreline_extrema(p.y, p.u, p.x, p.v),
      published_extrema(dir + "/reference/botella_peyret_extrema.csv"));
  return {n, 1.0 / n, summary.steps, seconds, worst};
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
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {out, /*quiet=*/true});
  const double seconds = seconds_since(start);
  const SeriesTable series = read_series_csv(work_dir + "/settling_disk_" + std::to_string(n_x) + "_bodies.csv");
  const SeriesTable ref = read_series_csv(dir + "/reference/ibms_settling_history.csv");
  const double speed = max_settling_speed(series.at("body_000/velocity_y"));
  const double speed_ref = max_settling_speed(ref.at("v"));
  return {n_x, 2.0 / n_x, summary.steps, seconds, std::abs(speed / speed_ref - 1.0)};
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
// consecutive points that bracket it; "not reached" (with the smallest error) otherwise.
std::string time_to_reach(const std::vector<Point>& points, double target) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (points[k].error > target) continue;
    if (k == 0) return "<= " + std::to_string(points[0].seconds) + " s (coarsest run already)";
    const Point& a = points[k - 1];
    const Point& b = points[k];
    const double w = std::log(target / a.error) / std::log(b.error / a.error);
    char text[64];
    std::snprintf(text, sizeof text, "%.3g s", std::exp(std::log(a.seconds) + w * std::log(b.seconds / a.seconds)));
    return text;
  }
  double best = HUGE_VAL;
  for (const Point& p : points) best = std::min(best, p.error);
  char text[64];
  std::snprintf(text, sizeof text, "not reached (smallest error %.3g)", best);
  return text;
}

struct Case {
  std::string name, error_definition;
  std::vector<int> quick, standard;
  std::function<Point(int, const std::string&)> run;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string level = argc > 1 ? argv[1] : "default";
  const std::string out_dir = argc > 2 ? argv[2] : IBMS_BENCH_OUTPUT_DIR;
  std::vector<std::string> only;
  for (int a = 3; a < argc; ++a) only.push_back(argv[a]);
  if (level != "quick" && level != "default" && level != "full") {
    std::fprintf(stderr, "usage: %s [quick|default|full] [out_dir] [case...]   (full: default + 192^2, 256^2 "
                 "for the Re 1000 cavity)\n", argv[0]);
    return 2;
  }
  const std::string work_dir = out_dir + "/work_precision_runs";
  std::filesystem::create_directories(work_dir);
  const std::vector<Case> cases{
      {"mms", "L2 norm of u - u_exact at t = 1 (unsteady manufactured solution, dt = 0.25 h)",
       {16, 32, 64, 128}, {16, 32, 64, 128, 256}, [](int n, const std::string&) { return run_mms(n); }},
      {"cavity_re100", "max |centre-line extremum - Botella & Peyret (1998)| over u_min, v_max, v_min, steady state",
       {16, 32, 48, 64}, {16, 32, 64, 96, 128},
       [](int n, const std::string& w) { return run_cavity("lid_driven_cavity_re100", n, w); }},
      {"cavity_re1000", "max |centre-line extremum - Botella & Peyret (1998)| over u_min, v_max, v_min, steady state",
       {32, 48, 64, 80}, {32, 48, 64, 96, 128},
       [](int n, const std::string& w) { return run_cavity("lid_driven_cavity_re1000", n, w); }},
      {"settling_disk", "|max settling speed / ibms 400x1200 reference - 1| (run to t = 0.7 s)",
       {40, 50, 60, 75}, {50, 75, 100, 150}, run_settling}};
  std::ofstream slopes(out_dir + "/work_precision_slopes.csv");
  slopes << "case,slope,n_points,error\n";
  for (const Case& c : cases) {
    if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
    std::printf("%s: %s\n  %6s %10s %8s %12s %12s\n", c.name.c_str(), c.error_definition.c_str(), "N", "h", "steps",
                "wall [s]", "error");
    std::vector<Point> points;
    std::vector<int> levels = level == "quick" ? c.quick : c.standard;
    if (level == "full" && c.name == "cavity_re1000") levels.insert(levels.end(), {192, 256});
    for (int n : levels) {
      points.push_back(c.run(n, work_dir));
      const Point& p = points.back();
      std::printf("  %6d %10.4g %8ld %12.4g %12.4e\n", p.n, p.h, p.steps, p.seconds, p.error);
      std::fflush(stdout);
    }
    const double slope = work_precision_slope(points);
    std::printf("  slope d log(error) / d log(wall time) = %.3f\n", slope);
    if (c.name.rfind("cavity", 0) == 0)  // the issue-13 marks: time to reach each error level
      for (double target : {1e-2, 3e-3, 1e-3})
        std::printf("  time to error %.0e: %s\n", target, time_to_reach(points, target).c_str());
    std::ofstream csv(out_dir + "/work_precision_" + c.name + ".csv");
    csv << "# bench_work_precision " << c.name << " (level " << level << "): error = " << c.error_definition << "\n";
    csv << "# least-squares slope of log(error) against log(wall_seconds) over all rows: " << slope << "\n";
    csv << "N,h,steps,wall_seconds,error\n";
    for (const Point& p : points) csv << p.n << "," << p.h << "," << p.steps << "," << p.seconds << "," << p.error << "\n";
    slopes << c.name << "," << slope << "," << points.size() << ",\"" << c.error_definition << "\"\n";
  }
  return 0;
}
