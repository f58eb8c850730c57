// Multi-direct forcing study, run on demand: 1, 2, 3 and 5 forcing passes
// (Luo et al. 2007) against the grid, on
//   - circular Couette flow between prescribed cylinders (verification/bodies/test_circular_couette:
//     start from the exact solution, t = 0.4, nu dt/h^2 = 0.5): L2 and max velocity error and rim
//     slip max|U - J u| after the step, relative to the inner rim speed;
//   - the rigid settling disk (validation/settling_disk/scene_rigid.toml, nu dt/h^2 <= 0.25), run to
//     touchdown: max settling speed against Glowinski et al.'s 5.53 cm/s, the largest rim slip over
//     the run relative to the speed, and the cost per step.
// Usage: bench_forcing_passes [quick|default|full]   (the disk: 1 and 3 passes at quick and default,
//        the papers' one and Luo et al.'s usual three; full adds 2 and 5 passes and D/h = 37.5 and 50)
//        bench_forcing_passes radius   the effective radius of the forced cylinders on the Couette
//        flow (CouetteResult: fitted A r + B / r) for 1 and 3 passes and marker retractions 0, 0.3,
//        0.5 h, with the errors: how much larger the immersed body looks than its rim, in cells;
//        then the same for ibm.coupling = "no_slip" on the cells and on the faces (radius_no_slip:
//        that part only).
// Writes <build>/bench/forcing_passes.csv.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_paths.hpp"
#include "scene/scene_reader.hpp"
#include "sim/time_step.hpp"
#include "sim/time_step_limits.hpp"
#include "verification/bodies/circular_couette.hpp"

using namespace ibms;
using clock_type = std::chrono::steady_clock;

namespace {

struct Row {
  std::string case_name;
  int passes = 0;
  double resolution = 0;  // cells per (inner) diameter
  double error_l2 = 0, error_max = 0, slip = 0, ms_per_step = 0;
};

Row couette(int n, int passes) {
  const test::CouetteResult r = test::run_circular_couette(n, passes);
  return {"couette", passes, 2 * test::CircularCouette::inner_radius * n, r.l2, r.max, r.slip, r.ms_per_step};
}

Row settling(int n_x, int passes) {
  const int markers = (2 * n_x) / 5;  // pi D / h with D = 0.25, h = 2 / n_x
  const Scene scene = read_scene_file(std::string(IBMS_SOURCE_DIR) + "/validation/settling_disk/scene_rigid.toml",
                                      {"domain.cells_x=" + std::to_string(n_x), "domain.cells_y=" + std::to_string(3 * n_x),
                                       "bodies.0.n_surface_points=" + std::to_string(markers),
                                       "ibm.forcing_passes=" + std::to_string(passes),
                                       // the passes of the papers' coupling (the scene ships the end-of-step one)
                                       "ibm.coupling=uhlmann", "ibm.marker_retraction=0"});
  Simulation sim(scene);
  VelocityScan scan = scan_velocity(sim.grid(), sim.fluid());
  double max_speed = 0, max_slip_ratio = 0;
  const auto start = clock_type::now();
  while (sim.rigid()[0].state.centre[1] > 0.14 && sim.fluid().time < scene.run.end_time) {
    advance_one_step(sim, next_time_step(sim, scan));
    scan = scan_velocity(sim.grid(), sim.fluid());
    const double speed = -sim.rigid()[0].state.velocity[1];
    max_speed = std::max(max_speed, speed);
    if (sim.fluid().step % 10 == 0 && speed > 0.5)
      max_slip_ratio = std::max(max_slip_ratio, test::rim_slip(sim, 0) / speed);
  }
  Row row{"settling_disk_rigid", passes, 0.25 / (2.0 / n_x)};
  row.ms_per_step = 1e3 * std::chrono::duration<double>(clock_type::now() - start).count() / sim.fluid().step;
  row.error_l2 = max_speed / 5.53 - 1.0;  // signed deviation of the max speed from Glowinski
  row.error_max = max_speed;
  row.slip = max_slip_ratio;
  return row;
}

}  // namespace

int radius_study(bool no_slip_only) {
  std::printf("circular Couette: effective radius growth (R1e - R1)/h, (R2 - R2e)/h from the fitted profile\n");
  std::printf("  coupling constrained passes retraction  D1/h  inner growth  outer growth   L2 error   max error\n");
  struct Setting { const char* coupling; int passes; const char* constrained = "cells"; };
  std::vector<Setting> settings{{"no_slip", 1, "cells"}, {"no_slip", 1, "faces"}};
  if (!no_slip_only) settings.insert(settings.begin(), {{"uhlmann", 1}, {"uhlmann", 3}});
  for (const Setting& s : settings)
    for (double retraction : {0.0, 0.3, 0.5})
      for (int n : {32, 64, 128}) {
        const test::CouetteResult r = test::run_circular_couette(n, s.passes, retraction, s.coupling, s.constrained);
        std::printf("  %8s %5s %6d %10.2f %5.1f  %12.3f  %12.3f  %9.3e  %9.3e\n", s.coupling, s.constrained, s.passes, retraction,
                    2 * test::CircularCouette::inner_radius * n, r.inner_growth_cells, r.outer_growth_cells, r.l2,
                    r.max);
        std::fflush(stdout);
      }
  return 0;
}

int main(int argc, char** argv) {
  const std::string level = argc > 1 ? argv[1] : "default";
  if (level == "radius") return radius_study(false);
  if (level == "radius_no_slip") return radius_study(true);
  const std::vector<int> passes{1, 2, 3, 5};
  const std::vector<int> disk_passes = level == "full" ? passes : std::vector<int>{1, 3};
  const std::vector<int> couette_grids = level == "quick" ? std::vector<int>{32, 64} : std::vector<int>{32, 64, 128};
  std::vector<int> disk_grids = level == "quick" ? std::vector<int>{100} : std::vector<int>{100, 150, 200};
  if (level == "full") disk_grids = {100, 150, 200, 300, 400};
  std::vector<Row> rows;
  std::printf("circular Couette (errors / rim slip relative to the inner rim speed, nu dt/h^2 = 0.5)\n");
  std::printf("  passes  D1/h   L2 error   max error  rim slip   ms/step\n");
  for (int p : passes)
    for (int n : couette_grids) {
      const Row r = couette(n, p);
      rows.push_back(r);
      std::printf("  %6d %5.1f  %9.3e  %9.3e  %9.3e  %7.2f\n", p, r.resolution, r.error_l2, r.error_max, r.slip,
                  r.ms_per_step);
    }
  std::printf("rigid settling disk (max speed vs 5.53 cm/s; rim slip / speed, largest over the run)\n");
  std::printf("  passes   D/h   max speed  deviation  rim slip   ms/step\n");
  for (int p : disk_passes)
    for (int n : disk_grids) {
      const Row r = settling(n, p);
      rows.push_back(r);
      std::printf("  %6d %5.2f  %9.4f  %+8.2f %%  %9.3e  %7.2f\n", p, r.resolution, r.error_max, 100 * r.error_l2,
                  r.slip, r.ms_per_step);
    }
  std::filesystem::create_directories(IBMS_BENCH_OUTPUT_DIR);
  std::ofstream csv(std::string(IBMS_BENCH_OUTPUT_DIR) + "/forcing_passes.csv");
  csv << "case,passes,cells_per_diameter,l2_error_or_speed_deviation,max_error_or_max_speed,rim_slip,ms_per_step\n";
  for (const Row& r : rows)
    csv << r.case_name << ',' << r.passes << ',' << r.resolution << ',' << r.error_l2 << ',' << r.error_max << ','
        << r.slip << ',' << r.ms_per_step << '\n';
  return 0;
}
