// Stability maps: time step against spring stiffness and against DEM stiffness,
// with the solid sub-stepped automatically (docs/method.md §5.3: n_sub = ceil(dt / dt_s)) or with a
// fixed single solid step per fluid step (Simulation::set_fixed_substeps(1)).
//   settling_spring   one disk settling in a closed 2 x 6 cm channel (the settling-disk scene on a
//                     40 x 120 grid, 16 rim points) to t = 0.1 s; dt x spring stiffness k_s;
//   collision_dem     two disks (D = 0.25 cm, rho_s = 2, k_s = 1e2, rim gap 0.05 cm) meeting head-on at
//                     10 cm/s (e_D = 0.9, CDS radius D/20) in a 2 x 1 cm box
//                     of fluid (40 x 20 grid, no gravity) to t = 0.08 s; dt x DEM stiffness k_Dn;
//   collision_spring  the same collision with k_Dn = 1e4; dt x spring stiffness k_s.
// A run is "stable" when it reaches its end with every state finite, its rim areas within 50 % of
// the start and (collisions) no body point faster than twice the initial approach speed: nothing
// drives the bodies (no gravity), so their points can only slow down, apart from the rebound
// and small spring vibrations, while an unstable contact or spring multiplies the speeds.
// "blow-up": the solver's own blow-up check stopped the run (its message names step, time,
// quantity and place; the bound crossed first, if any, is named before it); "too-deep": the
// solver stopped the run because a contact overlap exceeded the contact-sphere radius (a contact
// too soft for its spheres at this approach speed, the model's limit, not a numerical
// instability: at k_Dn = 1e2 the overlap v0 sqrt(m / k) is about the radius at every dt, and
// crosses it by under 1 % at some); "unstable": a bound
// was crossed but the run reached its end: the solver did not stop it (a transient instability,
// e.g. a contact rebounding far too fast, that does not diverge).
// Writes <out>/stability_<case>.csv (mode,dt,stiffness,substeps,outcome,max_area_change,
// max_speed_ratio,max_contact_pairs,message) and prints each map. Then one unstable fixed-step
// configuration is rerun through run_simulation to show that it stops with the message and that
// the series written up to then hold no NaN.
// usage: bench_stability [out_dir] [case...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "scene/scene_reader.hpp"
#include "sim/time_step.hpp"
#include "sim/checks/blow_up.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/run/run.hpp"
#include "solid/mass_spring_body.hpp"
#include "metrics/body_series.hpp"
#include "metrics/csv_reader.hpp"

#include "bench_paths.hpp"

using namespace ibms;

namespace {

struct Outcome {
  std::string kind = "stable";  // stable | unstable | blow-up | too-deep
  int max_substeps = 0;
  int max_active_pairs = 0;       // CDS pairs in contact (collisions: shows the bodies did touch)
  double max_area_change = 0.0, max_speed_ratio = 0.0;
  std::string message;
};

// Steps `scene` with fixed dt to its end_time, checking for blow-up after each step as run_simulation does.
Outcome run_case(const Scene& scene, bool fixed_steps, bool check_speed) {
  Simulation sim(scene);
  sim.set_fixed_substeps(fixed_steps ? 1 : 0);
  start_fluid_guard(sim);  // as run_simulation does before the first step
  Outcome out;
  std::vector<double> area0;
  for (const MassSpringBody& b : sim.bodies()) area0.push_back(polygon_area(b));
  const double speed0 = max_point_speed(sim.bodies());
  const double dt = scene.run.time_step;
  const long n_steps = std::lround(scene.run.end_time / dt);
  try {
    for (long s = 0; s < n_steps; ++s) {
      advance_one_step(sim, dt);
      check_for_blow_up(sim, dt, scan_velocity(sim.grid(), sim.fluid()));
      out.max_substeps = std::max(out.max_substeps, sim.stats().last_n_substeps);
      out.max_active_pairs = std::max(out.max_active_pairs, sim.stats().last_contact_stats.n_active_pairs);
      for (std::size_t b = 0; b < sim.bodies().size(); ++b)
        out.max_area_change = std::max(out.max_area_change, std::abs(polygon_area(sim.bodies()[b]) / area0[b] - 1));
      out.max_speed_ratio = std::max(out.max_speed_ratio, max_point_speed(sim.bodies()) / speed0);
      // The bounds mark the run, which goes on: the solver's own check may still stop it later.
      if (out.kind == "stable" && out.max_area_change > 0.5) {
        out.kind = "unstable";
        out.message = "rim area changed by more than 50 % at step " + std::to_string(sim.fluid().step);
      }
      if (out.kind == "stable" && check_speed && out.max_speed_ratio > 2.0) {
        out.kind = "unstable";
        out.message = "a body point moves at more than twice the initial speed at step " + std::to_string(sim.fluid().step);
      }
    }
  } catch (const BlowUpError& e) {
    // The depth stop alone (the solver's depth check, which reports only an overlap past the
    // smallest CDS radius), in a run that crossed no bound before: every other stop, or a run
    // already marked unstable, stays a failure.
    const bool too_deep = out.kind == "stable" &&
                          std::string(e.what()).find("exceeds the smallest contact-sphere radius") != std::string::npos;
    out.kind = too_deep ? "too-deep" : "blow-up";
    out.message = (out.message.empty() ? "" : out.message + "; then ") + e.what();
  }
  return out;
}

Scene settling_scene(double dt, double spring_stiffness) {
  Scene s = read_scene_file(std::string(IBMS_SOURCE_DIR) + "/validation/settling_disk/scene.toml",
                            {"ibm.coupling=uhlmann", "ibm.marker_retraction=0",  // the maps of the papers' coupling
                             "domain.cells_x=40", "domain.cells_y=120", "bodies.0.n_surface_points=16",
                             "run.end_time=0.1", "run.time_step=" + std::to_string(dt),
                             "bodies.0.spring_stiffness=" + std::to_string(spring_stiffness),
                             "bodies.0.spring_integrator=explicit"});  // the map of the explicit springs
  return s;
}

Scene collision_scene(double dt, double spring_stiffness, double dem_stiffness) {
  Scene s = read_scene_file(std::string(IBMS_SOURCE_DIR) + "/validation/settling_disk/scene.toml",
                            {"ibm.coupling=uhlmann", "ibm.marker_retraction=0",  // the maps of the papers' coupling
                             "domain.length_y=1.0", "domain.cells_x=40", "domain.cells_y=20", "bodies.0.centre=[0.85, 0.5]", "bodies.0.density=2.0",
                             "bodies.0.n_surface_points=16", "fluid.gravity=[0.0, 0.0]", "run.end_time=0.08",
                             "run.time_step=" + std::to_string(dt), "bodies.0.spring_stiffness=" + std::to_string(spring_stiffness),
                             "contact.stiffness=" + std::to_string(dem_stiffness), "contact.restitution_coefficient=0.9",
                             "contact.cds_radius_fraction=0.05", "bodies.0.spring_integrator=explicit"});
  s.bodies.push_back(s.bodies[0]);
  s.bodies[0].centre = {0.85, 0.5};  // rim gap 0.05 cm: the CDS touch after a few ms
  s.bodies[0].velocity = {5.0, 0.0};
  s.bodies[1].centre = {1.15, 0.5};
  s.bodies[1].velocity = {-5.0, 0.0};
  return s;
}

struct MapCase {
  std::string name, stiffness_name;
  std::vector<double> stiffness;
  std::function<Scene(double dt, double k)> scene;
  bool check_speed;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : IBMS_BENCH_OUTPUT_DIR;
  std::vector<std::string> only;
  for (int a = 2; a < argc; ++a) only.push_back(argv[a]);
  std::filesystem::create_directories(out_dir);
  const std::vector<double> time_steps{1e-4, 3e-4, 1e-3, 3e-3};  // [s]
  const std::vector<MapCase> cases{
      {"settling_spring", "spring_stiffness", {1e2, 1e3, 1e4, 1e5, 1e6, 1e7},
       [](double dt, double k) { return settling_scene(dt, k); }, false},
      {"collision_dem", "contact_stiffness", {1e2, 1e3, 1e4, 1e5, 1e6, 1e7},
       [](double dt, double k) { return collision_scene(dt, 1e2, k); }, true},
      {"collision_spring", "spring_stiffness", {1e2, 1e3, 1e4, 1e5, 1e6},
       [](double dt, double k) { return collision_scene(dt, k, 1e4); }, true}};
  int auto_failures = 0;
  for (const MapCase& c : cases) {
    if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
    std::ofstream csv(out_dir + "/stability_" + c.name + ".csv");
    csv << "# bench_stability " << c.name << ": fluid dt [s] against " << c.stiffness_name
        << " [dyn/cm^2 per unit depth]; mode auto = automatic solid sub-steps, fixed = one solid step per fluid step\n";
    csv << "mode,dt,stiffness,substeps,outcome,max_area_change,max_speed_ratio,max_contact_pairs,message\n";
    std::map<std::pair<int, int>, std::string> map[2];
    for (std::size_t ik = 0; ik < c.stiffness.size(); ++ik)
      for (std::size_t it = 0; it < time_steps.size(); ++it)
        for (int mode = 0; mode < 2; ++mode) {
          const Outcome o = run_case(c.scene(time_steps[it], c.stiffness[ik]), mode == 1, c.check_speed);
          map[mode][{static_cast<int>(ik), static_cast<int>(it)}] = o.kind;
          if (mode == 0 && o.kind != "stable" && o.kind != "too-deep") ++auto_failures;
          std::string message = o.message;
          std::replace(message.begin(), message.end(), '"', '\'');
          csv << (mode ? "fixed" : "auto") << "," << time_steps[it] << "," << c.stiffness[ik] << "," << o.max_substeps
              << "," << o.kind << "," << o.max_area_change << "," << o.max_speed_ratio << "," << o.max_active_pairs << ",\"" << message << "\"\n";
          csv.flush();
        }
    std::printf("%s: rows %s, columns dt [s]; each cell auto/fixed (S stable, U unstable, B blow-up stopped, D stopped: contact deeper than its spheres)\n",
                c.name.c_str(), c.stiffness_name.c_str());
    std::printf("  %10s", "");
    for (double dt : time_steps) std::printf(" %9.0e", dt);
    std::printf("\n");
    for (std::size_t ik = 0; ik < c.stiffness.size(); ++ik) {
      std::printf("  %10.0e", c.stiffness[ik]);
      for (std::size_t it = 0; it < time_steps.size(); ++it) {
        auto symbol = [&](int mode) { const std::string& k = map[mode][{static_cast<int>(ik), static_cast<int>(it)}];
                                      return k == "stable" ? 'S' : k == "blow-up" ? 'B' : k == "too-deep" ? 'D' : 'U'; };
        std::printf("       %c/%c", symbol(0), symbol(1));
      }
      std::printf("\n");
    }
    std::fflush(stdout);
  }
  // An unstable fixed-step run through the run loop: stops with the message, writes no NaN.
  if (only.empty() || std::find(only.begin(), only.end(), "demo") != only.end()) {
    Scene s = settling_scene(1e-3, 1e6);
    Simulation sim(s);
    sim.set_fixed_substeps(1);
    const std::string path = out_dir + "/demo_unstable_fixed_step.h5";
    try {
      run_simulation(sim, {path, /*quiet=*/true});
      std::printf("demo: the fixed-step run did not blow up\n");
    } catch (const BlowUpError& e) {
      const SeriesTable t = read_series_csv(out_dir + "/demo_unstable_fixed_step_bodies.csv");
      long non_finite = 0, values = 0;
      for (const auto& [name, column] : t)
        for (double v : column) { ++values; non_finite += !std::isfinite(v); }
      std::printf("demo (settling, k_s = 1e6, dt = 1e-3, fixed step): stopped: %s\n  written series: %ld values, %ld non-finite\n",
                  e.what(), values, non_finite);
    }
  }
  std::printf("automatic sub-stepping: %d unstable configuration(s)\n", auto_failures);
  return auto_failures > 0 ? 1 : 0;
}
