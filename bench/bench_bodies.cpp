// Body benchmarks, run on demand, printing figures: the cost of
// each pipeline stage per fluid step from the solver's own stage timers, for
//   - the settling disk (validation/settling_disk) at D/h = 12.5, 18.75, 25 (and more on request),
//     first 0.3 s of settling (the run's own adaptive time step);
//   - any further scene given on the command line, run to its end time (cavity cases with bodies).
// Columns: fluid = predictor + projection; IB = direct forcing (interpolate + spread, all passes;
// marker preparation, incl. sub-markers, is timed with the schedules under "other");
// solid = sub-stepped body update without contacts (springs, fluid reaction, inner-fluid inertia);
// contacts = DEM forces and pair search inside the solid sub-steps (with contact.time_stepping =
// "inner_loop": the whole inner loop, its neighbour lists and point updates); other = schedules,
// diagnostics and output. Ratios are against the fluid stage of the same run.
// Usage: bench_bodies SETTLING_SCENE [--cells 100,150,200] [--until 0.3] [--set k=v]... [--substep-modes]
//                     [--contact-modes] [--model-modes] [EXTRA_SCENE...]
//   (--set applies to the extra scenes, e.g. --set contact.stiffness=1e7 for the paper's DEM stiffness;
//    --substep-modes runs each extra scene with run.solid_substeps = per_group and = global and prints
//    the ratio of their wall times; --contact-modes runs each extra scene also with
//    contact.time_stepping = shared, every point of a group in contact at the contact sub-step,
//    and prints the ratio of the wall times and contact stages to the inner loop's; --model-modes
//    runs each extra scene also with contact.model = collision_time and with contacts off, and prints
//    the ratio of each wall time to the run without contacts; --cells "" skips the settling runs)
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_paths.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
#include "sim/simulation.hpp"

using namespace ibms;

namespace {

struct Figures {
  long steps = 0;
  double fluid = 0, ib = 0, solid = 0, contacts = 0, other = 0, wall = 0;
  long substeps = 0;       // most sub-steps of any body group, summed over steps
  long body_substeps = 0;  // sub-steps summed over bodies and steps (the solid's work)
  long inner_steps = 0;    // inner contact steps summed over groups and steps
};

Figures run_and_time(const std::string& scene_path, const std::vector<std::string>& overrides) {
  const Scene scene = read_scene_file(scene_path, overrides);
  Simulation sim(scene);
  const BenchScratch scratch("ibms_bench_bodies");
  const RunSummary summary = run_simulation(sim, {(scratch.path / "run.h5").string(), /*quiet=*/true});
  const StageTimers& t = sim.timers();
  Figures f;
  f.steps = summary.steps;
  f.fluid = t.seconds(Stage::predictor) + t.seconds(Stage::projection);
  f.ib = t.seconds(Stage::ib_forcing);
  f.contacts = t.seconds(Stage::contacts);
  f.solid = t.seconds(Stage::bodies) - f.contacts;
  f.other = t.seconds(Stage::schedules) + t.seconds(Stage::diagnostics) + t.seconds(Stage::output);
  f.wall = summary.wall_seconds;
  f.substeps = sim.stats().total_substeps;
  f.body_substeps = sim.stats().total_body_substeps;
  f.inner_steps = sim.stats().total_contact_inner_steps;
  return f;
}

void print_header() {
  std::printf("   %-28s %7s %9s %9s %9s %9s %9s %7s %7s %7s %8s %9s\n", "case", "steps", "fluid", "IB", "solid",
              "contacts", "other", "IB/fl", "sol/fl", "con/fl", "sub/step", "body-sub");
  std::printf("   %-28s %7s %9s %9s %9s %9s %9s %7s %7s %7s %8s %9s\n", "", "", "ms/step", "ms/step", "ms/step",
              "ms/step", "ms/step", "", "", "", "(most)", "/step");
}

void print_row(const std::string& name, const Figures& f) {
  if (f.steps == 0) {
    std::printf("   %-28s no steps run\n", name.c_str());
    return;
  }
  const double per = 1e3 / static_cast<double>(f.steps);
  std::printf("   %-28s %7ld %9.3f %9.3f %9.3f %9.3f %9.3f %7.3f %7.3f %7.3f %8.1f %9.1f\n", name.c_str(), f.steps,
              f.fluid * per, f.ib * per, f.solid * per, f.contacts * per, f.other * per, f.ib / f.fluid,
              f.solid / f.fluid, f.contacts / f.fluid, static_cast<double>(f.substeps) / f.steps,
              static_cast<double>(f.body_substeps) / f.steps);
}

std::vector<int> parse_list(const std::string& text) {
  std::vector<int> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(std::atoi(item.c_str()));
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_bodies SETTLING_SCENE [--cells 100,150,200] [--until 0.3] [--set k=v]... [SCENE...]\n");
    return 2;
  }
  std::vector<int> cells{100, 150, 200};
  std::string until = "0.3";
  std::vector<std::string> extra, extra_sets;
  bool substep_modes = false, contact_modes = false, model_modes = false;
  for (int a = 2; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--cells" && a + 1 < argc) cells = parse_list(argv[++a]);
    else if (arg == "--until" && a + 1 < argc) until = argv[++a];
    else if (arg == "--set" && a + 1 < argc) extra_sets.push_back(argv[++a]);
    else if (arg == "--substep-modes") substep_modes = true;
    else if (arg == "--contact-modes") contact_modes = true;
    else if (arg == "--model-modes") model_modes = true;
    else extra.push_back(arg);
  }
  try {
    std::printf("Stage cost per fluid step (solver stage timers, one run each; machine shared, noisy)\n");
    print_header();
    for (int n : cells) {
      // Markers spaced ~h: N_l = 0.4 n (D = 0.25 cm, width 2 cm), as the validation runs.
      const std::vector<std::string> sets{"domain.cells_x=" + std::to_string(n),
                                          "domain.cells_y=" + std::to_string(3 * n),
                                          "bodies.0.n_surface_points=" + std::to_string(2 * n / 5),
                                          "run.end_time=" + until};
      const Figures f = run_and_time(argv[1], sets);
      char name[64];
      std::snprintf(name, sizeof name, "settling %dx%d D/h=%.2f", n, 3 * n, 0.25 * n / 2.0);
      print_row(name, f);
    }
    for (const std::string& path : extra) {
      const std::string name = std::filesystem::path(path).parent_path().filename().string().substr(0, 14) + "/" +
                               std::filesystem::path(path).stem().string();
      const Figures f = run_and_time(path, extra_sets);
      print_row(name, f);
      std::printf("   %-28s wall %.1f s; inner contact steps %.1f per step\n", "", f.wall,
                  static_cast<double>(f.inner_steps) / static_cast<double>(std::max(1L, f.steps)));
      if (contact_modes) {
        std::vector<std::string> shared_sets = extra_sets;
        shared_sets.push_back("contact.time_stepping=shared");
        const Figures s = run_and_time(path, shared_sets);
        print_row(name.substr(0, 21) + " shared", s);
        std::printf("   %-28s wall %.1f s; shared / inner loop: wall %.2f, contact stage %.2f\n", "", s.wall,
                    s.wall / f.wall, s.contacts / f.contacts);
      }
      if (model_modes) {
        // The collision-time law (k per contact, T_c = collision_steps dt) and no contacts at all.
        std::vector<std::string> collision_sets = extra_sets, off_sets = extra_sets;
        collision_sets.insert(collision_sets.end(), {"contact.model=collision_time", "contact.stiffness=0"});
        off_sets.insert(off_sets.end(), {"contact.model=linear", "contact.stiffness=0"});
        const Figures c = run_and_time(path, collision_sets);
        print_row(name.substr(0, 21) + " coll_t", c);
        const Figures o = run_and_time(path, off_sets);
        print_row(name.substr(0, 21) + " off", o);
        std::printf("   %-28s wall %.1f s (collision_time), %.1f s (off); / off: collision_time %.2f, %s %.2f\n", "",
                    c.wall, o.wall, c.wall / o.wall, "scene's law", f.wall / o.wall);
      }
      if (!substep_modes) continue;
      std::vector<std::string> global_sets = extra_sets;
      global_sets.push_back("run.solid_substeps=global");
      const Figures g = run_and_time(path, global_sets);
      print_row(name.substr(0, 21) + " global", g);
      std::printf("   %-28s wall %.1f s; global / per_group: wall %.2f, body sub-steps %.2f\n", "", g.wall,
                  g.wall / f.wall, static_cast<double>(g.body_substeps) / static_cast<double>(f.body_substeps));
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_bodies: %s\n", error.what());
    return 1;
  }
  return 0;
}
