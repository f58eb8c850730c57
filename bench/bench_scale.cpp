// How the cost of a step grows with the number of bodies, run on demand, printing figures: n x n
// bodies settling in a closed box of fluid, the box and its grid growing with them (1.6 D per body
// and direction, D/h = 16, 50 rim points each), the papers' contacts (k_Dn = 1e7, e_D = 0.5, CDS
// on the rim points, walls on), series every 10 steps, the final snapshot and checkpoint, one
// thread, a fixed step. Kinds: rigid disks, mass-spring wheels, swelling wheels; optionally a
// resting bed (the bodies start in touch, their contact spheres touching, rows from the floor up). For each run it
// prints each stage's time per step from the solver's own timers and its ratio to the fluid stages
// (predictor + projection), and for each kind the least-squares exponent p of cost per step ~ N^p
// over the numbers of bodies run (N = n^2).
// --collision-time: contact.model = "collision_time" (the linear law with k and c chosen per contact
// so that it lasts 10 fluid steps, docs/method.md §5.5) instead of the papers' k_Dn = 1e7.
// --coupling no_slip: the end-of-step constraint on the face velocities (docs/method.md §3.7) instead
// of the papers' coupling (ibm.coupling = "uhlmann", the default); --drift X: its
// ibm.preconditioner_drift (0 by default: each moving body's block built again at every move).
// --outer-fraction F: contact.outer_step_fraction (the inner loop's outer step, docs/method.md §5.4).
// --restitution E: e_D of the bodies and the walls (0.5 by default).
// --scene FILE: write the scene of the first size and kind to FILE (its output FILE with .h5 for .toml)
// instead of running anything, so that `ibms run FILE` repeats a bench run and keeps its output.
// --report DIR: the report's sets, written to DIR/scale.csv (rigid disks and wheels at 16 to 1024
// bodies; beds of 64 with the papers' law, the wheels also at outer step 0.5 and with collision time).
// Usage: bench_scale [--n 4,8,16,32] [--kinds rigid,wheel,swelling] [--steps 40] [--bed] [--collision-time]
//                    [--coupling uhlmann|no_slip] [--drift X] [--outer-fraction F] [--restitution E]
//                    [--scene FILE]
//        bench_scale --report DIR
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_paths.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
#include "sim/simulation.hpp"

using namespace ibms;

namespace {

constexpr double diameter = 1.0, spacing = 1.6;  // D, and the box per body and direction [length]
constexpr int cells_per_diameter = 16, rim_points = 50;

// What the command line chooses for every run.
struct Options {
  int steps = 40;
  bool bed = false, collision_time = false;
  std::string coupling = "uhlmann";
  double drift = 0.0;
  double outer_step_fraction = 0.0;  // contact.outer_step_fraction; 0: the scene's default
  double restitution = 0.5;          // e_D of the bodies and the walls
};

// The scene of n x n bodies of `kind` (rigid | wheel | swelling) as TOML.
std::string scene_text(int n, const std::string& kind, const Options& o, const std::string& output) {
  const int steps = o.steps;
  const bool bed = o.bed, collision_time = o.collision_time;
  const std::string& coupling = o.coupling;
  const double drift = o.drift;
  const double length = spacing * n;
  const int cells = static_cast<int>(std::lround(length * cells_per_diameter / diameter));
  std::string text = fmt::format(R"([run]
end_time = {}
time_step = 0.002
[domain]
length_x = {}
length_y = {}
cells_x = {}
cells_y = {}
[fluid]
density = 1.0
kinematic_viscosity = 0.01
gravity = [0.0, -10.0]
[ibm]
kernel = "roma3"
coupling = "{}"
{}
)", 0.002 * steps, length, length, cells, cells, coupling,
                                 coupling == "no_slip"
                                     ? fmt::format("constrained_velocity = \"faces\"\npreconditioner_drift = {}", drift)
                                     : "");
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Spread over the box, or a bed: rows from the floor up, centred, the contact spheres (radius
      // r = h/2) of neighbours and of the bottom row and the floor just touching, so that gravity
      // loads the contacts from zero (rims exactly D apart would put rim points of neighbours on
      // one another).
      const double r = 0.5 * diameter / cells_per_diameter, pitch = diameter + 2.0 * r;
      const double x = bed ? 0.5 * length + (i - 0.5 * (n - 1)) * pitch : (i + 0.5) * spacing;
      const double y = bed ? 0.5 * diameter + r + j * pitch : (j + 0.5) * spacing;
      text += fmt::format("[[bodies]]\ncentre = [{}, {}]\ndiameter = {}\nn_surface_points = {}\ndensity = 1.5\n", x, y,
                          diameter, rim_points);
      if (kind == "rigid") text += "kind = \"rigid\"\n";
      else text += fmt::format("spring_stiffness = 2.0e4\nrestitution_coefficient = {}\n", o.restitution);
      if (kind == "swelling")
        text += "[bodies.swelling]\nonset_time = 0.0\nrate = 0.1\nmax_diameter = 1.1\n";
    }
  text += collision_time ? "[contact]\nmodel = \"collision_time\"\n" : "[contact]\nstiffness = 1.0e7\n";
  if (o.outer_step_fraction > 0.0) text += fmt::format("outer_step_fraction = {}\n", o.outer_step_fraction);
  text += fmt::format(R"(restitution_coefficient = {}
cds_radius = {}
walls = true
[output]
file = "{}"
series_every = 10
centreline_profiles = false
progress = false
)", o.restitution, 0.5 * diameter / cells_per_diameter, output);
  return text;
}

struct Figures {
  int bodies = 0, cells = 0;
  long steps = 0;
  double fluid = 0, ib = 0, bodies_stage = 0, contacts = 0, output = 0, other = 0, wall = 0;
};

Figures run(int n, const std::string& kind, const Options& o) {
  const BenchScratch scratch("ibms_bench_scale");
  const std::string out = (scratch.path / "run.h5").string();
  const Scene scene = read_scene_string(scene_text(n, kind, o, out), "bench_scale.toml");
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {out, /*quiet=*/true});
  const StageTimers& t = sim.timers();
  Figures f;
  f.bodies = n * n;
  f.cells = scene.domain.cells_x * scene.domain.cells_y;
  f.steps = summary.steps;
  f.fluid = t.seconds(Stage::predictor) + t.seconds(Stage::projection);
  f.ib = t.seconds(Stage::ib_forcing) + t.seconds(Stage::schedules);
  f.contacts = t.seconds(Stage::contacts);
  f.bodies_stage = t.seconds(Stage::bodies);
  f.output = t.seconds(Stage::output);
  f.other = t.seconds(Stage::diagnostics);
  f.wall = summary.wall_seconds;
  return f;
}

// Least-squares slope of log y against log x.
double exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

// One table row: a run's stages in ms per step and their ratios to the fluid stages.
void print_row(const std::string& kind, const Figures& f) {
  const double per = 1e3 / static_cast<double>(f.steps);
  std::printf("  %-9s %6d %8d | %25.3f %8.3f %8.3f %8.3f %8.3f %8.3f | %16.2f %6.2f %6.2f %6.2f\n", kind.c_str(),
              f.bodies, f.cells, f.fluid * per, f.ib * per, f.bodies_stage * per, f.contacts * per, f.output * per,
              f.wall * per, f.ib / f.fluid, f.bodies_stage / f.fluid, f.output / f.fluid, f.wall / f.fluid);
  std::fflush(stdout);
}

void print_header(const Options& o) {
  std::printf("bench_scale: n x n bodies, D/h = %d, %d rim points, %s%s, coupling %s%s, series every 10 steps, "
              "%d steps%s, one thread\n", cells_per_diameter, rim_points,
              o.collision_time ? "collision-time contacts (10 steps)" : "k_Dn = 1e7",
              o.outer_step_fraction > 0.0
                  ? fmt::format(", outer step {} of the springs' sub-step", o.outer_step_fraction).c_str()
                  : "",
              o.coupling.c_str(),
              o.coupling == "no_slip" ? fmt::format(" (preconditioner_drift {})", o.drift).c_str() : "", o.steps,
              o.bed ? ", a resting bed" : "");
  std::printf("  %-9s %6s %8s | ms per step: %8s %8s %8s %8s %8s %8s | / fluid: %6s %6s %6s %6s\n", "kind", "bodies",
              "cells", "fluid", "IB", "bodies", "contacts", "output", "run", "IB", "bodies", "output", "run");
}

// Runs every kind at every size of one set, prints its table and exponents, and appends its rows
// (set name first) to csv when it is open.
void run_set(const std::string& set, const std::vector<std::string>& sizes, const std::vector<std::string>& kinds,
             const Options& o, std::FILE* csv) {
  print_header(o);
  for (const std::string& kind : kinds) {
    std::vector<double> n_bodies, per_step, fluid_per_step;
    for (const std::string& size : sizes) {
      const Figures f = run(std::atoi(size.c_str()), kind, o);
      print_row(kind, f);
      if (csv != nullptr) {
        const double per = 1e3 / static_cast<double>(f.steps);
        std::fprintf(csv, "%s,%s,%d,%d,%ld,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", set.c_str(), kind.c_str(), f.bodies,
                     f.cells, f.steps, f.fluid * per, f.ib * per, f.bodies_stage * per, f.contacts * per,
                     f.output * per, f.wall * per);
        std::fflush(csv);
      }
      n_bodies.push_back(f.bodies);
      per_step.push_back(f.wall / f.steps);
      fluid_per_step.push_back(f.fluid / f.steps);
    }
    if (n_bodies.size() > 1)
      std::printf("  %-9s cost per step ~ N^%.2f (the fluid stages ~ N^%.2f; cells grow like N)\n", kind.c_str(),
                  exponent(n_bodies, per_step), exponent(n_bodies, fluid_per_step));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> sizes{"4", "8", "16", "32"}, kinds{"rigid", "wheel", "swelling"};
  Options o;
  std::string report_dir, scene_file;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--n" && a + 1 < argc) sizes = split(argv[++a]);
    else if (arg == "--kinds" && a + 1 < argc) kinds = split(argv[++a]);
    else if (arg == "--steps" && a + 1 < argc) o.steps = std::atoi(argv[++a]);
    else if (arg == "--bed") o.bed = true;
    else if (arg == "--collision-time") o.collision_time = true;
    else if (arg == "--coupling" && a + 1 < argc && (std::string(argv[a + 1]) == "uhlmann" ||
                                                     std::string(argv[a + 1]) == "no_slip"))
      o.coupling = argv[++a];
    else if (arg == "--drift" && a + 1 < argc) o.drift = std::atof(argv[++a]);
    else if (arg == "--outer-fraction" && a + 1 < argc && std::atof(argv[a + 1]) > 0.0 && std::atof(argv[a + 1]) <= 1.0)
      o.outer_step_fraction = std::atof(argv[++a]);
    else if (arg == "--restitution" && a + 1 < argc && std::atof(argv[a + 1]) >= 0.0 && std::atof(argv[a + 1]) <= 1.0)
      o.restitution = std::atof(argv[++a]);
    else if (arg == "--scene" && a + 1 < argc) scene_file = argv[++a];
    else if (arg == "--report" && a + 1 < argc) report_dir = argv[++a];
    else {
      std::fprintf(stderr, "usage: bench_scale [--n 4,8,16,32] [--kinds rigid,wheel,swelling] [--steps 40] [--bed] "
                           "[--collision-time] [--coupling uhlmann|no_slip] [--drift X] [--outer-fraction F in (0, 1]] "
                           "[--restitution E in [0, 1]] [--scene FILE]\n"
                           "       bench_scale --report DIR [--steps 40]\n");
      return 2;
    }
  }
  try {
    if (!scene_file.empty()) {
      std::filesystem::path output(scene_file);
      output.replace_extension(".h5");
      const std::string text = scene_text(std::stoi(sizes.front()), kinds.front(), o, output.string());
      read_scene_string(text, scene_file);  // the bench's own scene: refuse one the solver would refuse
      std::ofstream file(scene_file);
      file << text;
      if (!file.flush()) throw std::runtime_error("cannot write " + scene_file);
      std::printf("written %s (ibms run %s writes %s)\n", scene_file.c_str(), scene_file.c_str(),
                  output.string().c_str());
      return 0;
    }
    if (report_dir.empty()) {
      run_set("", sizes, kinds, o, nullptr);
      return 0;
    }
    // The report's sets (DIR/scale.csv): rigid disks and wheels at 16 to 1024 bodies, and the beds of
    // 64 at the papers' stiffness, the wheels also at half the springs' sub-step and with the
    // collision-time law.
    // Every set from the defaults (the papers' coupling and law), only the step count taken.
    Options base;
    base.steps = o.steps;
    const std::string path = report_dir + "/scale.csv";
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
    std::FILE* csv = file.get();
    if (csv == nullptr) throw std::runtime_error("cannot write " + path);
    std::fprintf(csv, "# bench_scale --report: ms per step from the solver's stage timers, one thread, %d steps\n",
                 base.steps);
    std::fprintf(csv, "set,kind,bodies,cells,steps,fluid,ib,bodies_stage,contacts,output,run\n");
    run_set("spread", {"4", "8", "16", "32"}, {"rigid", "wheel"}, base, csv);
    Options bed = base;
    bed.bed = true;
    run_set("bed", {"8"}, {"rigid", "wheel"}, bed, csv);
    Options half = bed;
    half.outer_step_fraction = 0.5;
    run_set("bed_outer_step_0.5", {"8"}, {"wheel"}, half, csv);
    Options collision = bed;
    collision.collision_time = true;
    run_set("bed_collision_time", {"8"}, {"rigid", "wheel"}, collision, csv);
    std::printf("written %s\n", path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_scale: %s\n", e.what());
    return 1;
  }
  return 0;
}
