// Fluid stability maps: CFL number against cell Reynolds number Re_h = U h / nu
// (viscous number D = nu dt / h^2), no bodies, two flows:
//   cavity       lid-driven cavity, unit square, lid speed U = 1, N^2 cells, from rest to t = T L/U;
//   shear_layer  doubly periodic double shear layer (Bell, Colella & Glaz 1989; Minion & Brown 1997):
//                u = tanh((y - 1/4)/delta) for y <= 1/2, tanh((3/4 - y)/delta) above, delta = 1/30,
//                v = 0.05 sin(2 pi x), unit box, U = 1, N^2 cells, to t = T L/U;
// each twice: with a fixed time step dt = C h / U (C = U dt / h, D = C / Re_h), and with the
// adaptive step of run_simulation at run.cfl = C (dt = C / max(|u|/dx + |v|/dy), with the lid speed
// in the cavity; the map "<case>_adaptive"). Default N = 64, T = 10.
// Each point is stepped with advance_one_step and the solver's blow-up check (check_for_blow_up) as
// run_simulation does, and gives two outcomes (the check only reads the state, so one run serves both):
//   default_guard  the shipped run.max_cfl (RunSpec default), the fluid guard (energy budget and
//                  speed bound, sim/checks/fluid_guard.hpp) and the non-finite check;
//   no_cfl_guard   only the non-finite check (the run goes on after a guard fired).
// Outcome "stable": finite to the end, no velocity component above 2 U, and the kinetic energy
// E = 0.5 sum |u|^2 dx dy never above its bound: cavity 0.5 U^2 L^2 (the whole box moving at the lid
// speed); shear layer 1.01 E(0) (the central convection in divergence form with divergence-free face
// velocities conserves E, viscosity and the projection only remove it). "unstable": a bound was
// crossed and no check stopped the
// run (a run is cut once E passes 1e6 bounds, said in the message: only an overflow would trip the
// non-finite check, and an adaptive step would shrink without end). "stopped": the solver's check
// stopped it (message kept; a bound crossed before it is named first).
// Writes <out>/stability_fluid_<case>[_adaptive][_<N>][_t<T>].csv (mode,cfl,cell_reynolds,
// viscous_number,dt,nu,theory_max_g,steps,outcome,max_cfl_measured,max_energy_ratio,end_energy_ratio,
// late_energy_ratio,max_speed,first_above_cfl_1,first_above_cfl_2,first_above_bound,max_speed_over_scale,
// max_energy_over_budget,message) and
// prints each map beside the von Neumann limit (fluid/time_scheme_stability.hpp).
// usage: bench_fluid_stability [out_dir] [--cells N] [--flow-times T] [cavity] [shear_layer]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "fluid/time_scheme_stability.hpp"
#include "scene/scene_reader.hpp"
#include "sim/checks/blow_up.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"

#include "bench_paths.hpp"

using namespace ibms;

namespace {

constexpr double runaway_factor = 1e6;  // a run whose energy passes this many bounds is cut
// A velocity component above this many U is unstable too: a grid-scale oscillation confined to a
// few cells can grow far while the energy stays within its bound (the stable runs of the 64^2 maps
// stay below 1.42 U, including the transient of the impulsively started lid, apart from marginal
// points: docs/fluid-stability.md).
constexpr double max_speed_ratio = 2.0;

struct Point {
  double cfl, cell_reynolds;
};

struct Outcome {
  std::string guarded = "stable", unguarded = "stable";  // stable | unstable | stopped
  std::string guarded_message, unguarded_message;
  long steps = 0;
  double max_cfl_measured = 0.0, max_energy_ratio = 0.0, end_energy_ratio = 0.0;
  double late_energy_ratio = 0.0;  // E(end) / E(half-way): > 1 still growing at the end
  double max_speed = 0.0;          // largest |u| or |v| seen, over U
  // First step whose CFL number dt max(|u|/dx + |v|/dy) exceeds 1 and 2 (where a guard at that
  // run.max_cfl would stop), and the first step above the energy or speed bound; -1: never.
  long first_above_cfl_1 = -1, first_above_cfl_2 = -1, first_above_bound = -1;
  double mean_dt = 0.0;            // end time reached / steps (the adaptive step varies)
  // The fluid guard's figures over the run (sim/checks/fluid_guard.hpp): the largest max |u| / V_f and
  // E / budget (the guard stops at speed_factor and 1).
  double max_speed_over_scale = 0.0, max_energy_over_budget = 0.0;
};

struct MapCase {
  std::string name, description;
  std::function<Scene(int cells, double dt, double nu, double end_time)> scene;
  std::function<void(Simulation&)> initial_state;  // fluid at rest when empty
  // Energy bound from the initial energy and the box area.
  std::function<double(double initial_energy, double area)> energy_bound;
  std::string bound_text;
};

// Steps `scene` to its end_time with its fixed run.time_step, or with the adaptive step of
// run_simulation (next_time_step: run.cfl) when `adaptive`; see the file comment for the outcomes.
Outcome run_point(const MapCase& c, const Scene& scene, bool adaptive) {
  Simulation sim(scene);
  if (c.initial_state) c.initial_state(sim);
  start_fluid_guard(sim);  // as run_simulation does: the field set here is the initial one
  const Grid& g = sim.grid();
  const FluidSolver& solver = sim.fluid_solver();
  const double area = g.length_x * g.length_y;
  const double energy0 = solver.kinetic_energy(sim.fluid());
  const double bound = c.energy_bound(energy0, area);
  const double end_time = scene.run.end_time, time_tolerance = 1e-12 * end_time;
  double energy_half = energy0;
  bool half_seen = false;
  Outcome out;
  std::string crossed;  // the bound crossing, when it happened
  VelocityScan scan = scan_velocity(g, sim.fluid());
  while (sim.fluid().time < end_time - time_tolerance) {
    const double dt = adaptive ? next_time_step(sim, scan) : std::min(scene.run.time_step, end_time - sim.fluid().time);
    advance_one_step(sim, dt);
    scan = scan_velocity(g, sim.fluid());
    const long step = sim.fluid().step;
    out.steps = step;
    try {
      check_for_blow_up(sim, dt, scan);
    } catch (const BlowUpError& e) {
      if (out.guarded != "stopped") {
        out.guarded = "stopped";
        out.guarded_message = (crossed.empty() ? "" : crossed + "; then ") + e.what();
      }
      if (!scan.finite) {  // the check that stays without the CFL guard
        out.unguarded = "stopped";
        out.unguarded_message = (crossed.empty() ? "" : crossed + "; then ") + e.what();
        break;
      }
    }
    out.max_speed_over_scale = std::max(out.max_speed_over_scale, scan.max_speed / sim.instability().fluid_guard.speed_scale);
    out.max_energy_over_budget = std::max(out.max_energy_over_budget, scan.kinetic_energy / sim.instability().fluid_guard.energy_budget());
    const double cfl = dt * scan.max_rate;
    out.max_cfl_measured = std::max(out.max_cfl_measured, cfl);
    if (cfl > 1.0 && out.first_above_cfl_1 < 0) out.first_above_cfl_1 = step;
    if (cfl > 2.0 && out.first_above_cfl_2 < 0) out.first_above_cfl_2 = step;
    const double energy = solver.kinetic_energy(sim.fluid());
    if (!half_seen && sim.fluid().time >= 0.5 * end_time) { energy_half = energy; half_seen = true; }
    out.max_energy_ratio = std::max(out.max_energy_ratio, energy / bound);
    out.end_energy_ratio = energy / bound;
    out.late_energy_ratio = energy / energy_half;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        out.max_speed = std::max({out.max_speed, std::abs(sim.fluid().velocity_x(i, j)),
                                  std::abs(sim.fluid().velocity_y(i, j))});
    if (crossed.empty() && (energy > bound || out.max_speed > max_speed_ratio)) {
      out.first_above_bound = step;
      crossed = energy > bound ? "kinetic energy " + std::to_string(energy) + " above the bound " +
                                     std::to_string(bound) + " (" + c.bound_text + ")"
                               : "a velocity component of " + std::to_string(out.max_speed) + " U (above 2 U)";
      crossed += " at step " + std::to_string(step) + ", t = " + std::to_string(sim.fluid().time);
      if (out.guarded == "stable") { out.guarded = "unstable"; out.guarded_message = crossed; }
      out.unguarded = "unstable";
      out.unguarded_message = crossed;
    }
    // Diverging: only an overflow would trip the non-finite check, and an adaptive step would
    // shrink without end. Cut the run here.
    if (energy > runaway_factor * bound) {
      const std::string cut = "; run cut at step " + std::to_string(step) + ", t = " + std::to_string(sim.fluid().time) +
                              " with the energy above 1e6 bounds, no check had stopped it";
      out.unguarded_message += cut;
      if (out.guarded == "unstable") out.guarded_message += cut;
      break;
    }
  }
  out.mean_dt = out.steps > 0 ? sim.fluid().time / out.steps : 0.0;
  return out;
}

Scene cavity_scene(int cells, double dt, double nu, double end_time, const std::string& out_dir) {
  return read_scene_file(std::string(IBMS_SOURCE_DIR) + "/validation/lid_driven_cavity_re1000/scene.toml",
                         {"domain.cells_x=" + std::to_string(cells), "domain.cells_y=" + std::to_string(cells),
                          "fluid.kinematic_viscosity=" + std::to_string(nu), "run.time_step=" + std::to_string(dt),
                          "run.end_time=" + std::to_string(end_time), "run.steady_tolerance=0",
                          // the central scheme of the von Neumann limit the maps are set against
                          "fluid.convection=central", "fluid.wall_closure=linear",
                          "output.file=\"" + out_dir + "/fluid_stability.h5\""});
}

Scene shear_layer_scene(int cells, double dt, double nu, double end_time, const std::string& out_dir) {
  // Dimensionless: unit box, velocity scale U = 1 (the tanh amplitude), rho_f = 1.
  const std::string text =
      "[run]\nend_time = 1.0\n"
      "[domain]\nlength_x = 1.0\nlength_y = 1.0\ncells_x = 64\ncells_y = 64\nperiodic_x = true\nperiodic_y = true\n"
      "[fluid]\nkinematic_viscosity = 0.01\n";
  return read_scene_string(text, "shear_layer (bench_fluid_stability)",
                           {"domain.cells_x=" + std::to_string(cells), "domain.cells_y=" + std::to_string(cells),
                            "fluid.kinematic_viscosity=" + std::to_string(nu), "run.time_step=" + std::to_string(dt),
                            "run.end_time=" + std::to_string(end_time),
                            "output.file=\"" + out_dir + "/fluid_stability.h5\""});
}

void set_double_shear_layer(Simulation& sim) {
  constexpr double thickness = 1.0 / 30.0, perturbation = 0.05;  // delta, v amplitude
  const Grid& g = sim.grid();
  FluidState& f = sim.fluid();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.x_centre(i), y = g.y_centre(j);
      f.velocity_x(i, j) = y <= 0.5 ? std::tanh((y - 0.25) / thickness) : std::tanh((0.75 - y) / thickness);
      f.velocity_y(i, j) = perturbation * std::sin(2 * pi * x);
    }
  sim.fluid_solver().initialise_faces(f);  // divergence-free faces (the field already is, to O(h^2))
}

char symbol(const std::string& kind) { return kind == "stable" ? 'S' : kind == "unstable" ? 'U' : 'X'; }

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = IBMS_BENCH_OUTPUT_DIR;
  int cells = 64;
  double flow_times = 10.0;
  std::vector<std::string> only;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--cells" && a + 1 < argc) cells = std::atoi(argv[++a]);
    else if (arg == "--flow-times" && a + 1 < argc) flow_times = std::atof(argv[++a]);
    else if (arg == "cavity" || arg == "shear_layer") only.push_back(arg);
    else out_dir = arg;
  }
  std::filesystem::create_directories(out_dir);
  const std::vector<double> fixed_cfls{0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1.0, 1.25, 1.5, 2.0};
  const std::vector<double> adaptive_cfls{0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1.0, 1.25, 1.5};
  const std::vector<double> cell_reynolds{0.25, 0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512};
  const std::vector<MapCase> cases{
      {"cavity", "lid-driven cavity, lid speed U = 1, from rest",
       [&](int n, double dt, double nu, double t) { return cavity_scene(n, dt, nu, t, out_dir); }, nullptr,
       [](double, double area) { return 0.5 * area; }, "0.5 U^2 L^2"},
      {"shear_layer", "doubly periodic double shear layer, delta = 1/30, U = 1",
       [&](int n, double dt, double nu, double t) { return shear_layer_scene(n, dt, nu, t, out_dir); },
       set_double_shear_layer, [](double energy0, double) { return 1.01 * energy0; }, "1.01 E(0)"}};
  const double default_max_cfl = RunSpec{}.max_cfl;
  for (const MapCase& c : cases) {
    if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
    for (const bool adaptive : {false, true}) {
      const std::vector<double>& cfls = adaptive ? adaptive_cfls : fixed_cfls;
      char horizon[32];
      std::snprintf(horizon, sizeof horizon, "_t%g", flow_times);
      const std::string name = c.name + (adaptive ? "_adaptive" : "") + (cells == 64 ? "" : "_" + std::to_string(cells)) +
                               (flow_times == 10.0 ? "" : horizon);
      std::ofstream csv(out_dir + "/stability_fluid_" + name + ".csv");
      csv << "# bench_fluid_stability " << name << ": "
          << (adaptive ? "run.cfl of the adaptive time step (dt = run.cfl / max(|u|/dx + |v|/dy))"
                       : "CFL number U dt / h, fixed dt,")
          << " against cell Reynolds number U h / nu; " << c.description << "; " << cells << "^2 cells, to t = "
          << flow_times << " L/U" << (adaptive ? "; dt and viscous_number: mean over the run" : "") << "\n";
      csv << "# mode default_guard = run.max_cfl " << default_max_cfl << " (the default), the fluid guard and the non-finite check; "
          << "no_cfl_guard = the non-finite check only; energy bound " << c.bound_text
          << " and a velocity component at most 2 U; first_above_*: first step with CFL number > 1, > 2, "
             "energy or speed above its bound (-1 never)\n";
      csv << "mode,cfl,cell_reynolds,viscous_number,dt,nu,theory_max_g,steps,outcome,max_cfl_measured,"
             "max_energy_ratio,end_energy_ratio,late_energy_ratio,max_speed,first_above_cfl_1,first_above_cfl_2,"
             "first_above_bound,max_speed_over_scale,max_energy_over_budget,message\n";
      const double h = 1.0 / cells, speed = 1.0;
      std::map<std::pair<std::size_t, std::size_t>, Outcome> map;
      for (std::size_t ir = 0; ir < cell_reynolds.size(); ++ir)
        for (std::size_t ic = 0; ic < cfls.size(); ++ic) {
          const double nu = speed * h / cell_reynolds[ir];
          Scene scene = c.scene(cells, adaptive ? 0.0 : cfls[ic] * h / speed, nu, flow_times);
          // Set here, not by --set: the scene check refuses run.cfl >= run.max_cfl, and this map
          // runs such targets on purpose under the default guard.
          if (adaptive) scene.run.cfl = cfls[ic];
          const Outcome o = run_point(c, scene, adaptive);
          map[{ir, ic}] = o;
          const double dt = adaptive ? o.mean_dt : scene.run.time_step;
          const double viscous_number = nu * dt / (h * h);
          const double theory = ab2_cn_max_amplification(cfls[ic], viscous_number);
          for (int mode = 0; mode < 2; ++mode) {
            std::string message = mode == 0 ? o.guarded_message : o.unguarded_message;
            std::replace(message.begin(), message.end(), '"', '\'');
            char line[512];
            std::snprintf(line, sizeof line, "%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.8f,%ld,%s,%.4g,%.4g,%.4g,%.4g,%.4g,%ld,%ld,%ld,%.4g,%.4g,",
                          mode == 0 ? "default_guard" : "no_cfl_guard", cfls[ic], cell_reynolds[ir], viscous_number,
                          dt, nu, theory, o.steps, (mode == 0 ? o.guarded : o.unguarded).c_str(), o.max_cfl_measured,
                          o.max_energy_ratio, o.end_energy_ratio, o.late_energy_ratio, o.max_speed,
                          o.first_above_cfl_1, o.first_above_cfl_2, o.first_above_bound, o.max_speed_over_scale,
                          o.max_energy_over_budget);
            csv << line << "\"" << message << "\"\n";
          }
          csv.flush();
        }
      std::printf("%s (%d^2, t = %g L/U): rows Re_h = U h / nu, columns %s; each cell default guard / no CFL guard "
                  "(S stable, U unstable, X stopped by the solver's check); * = von Neumann unstable at that CFL and "
                  "%s\n", name.c_str(), cells, flow_times, adaptive ? "run.cfl (adaptive dt)" : "CFL = U dt / h (fixed dt)",
                  adaptive ? "the run's mean nu dt / h^2" : "nu dt / h^2 = CFL / Re_h");
      std::printf("  %6s", "");
      for (double cfl : cfls) std::printf(" %6.2f", cfl);
      std::printf("\n");
      for (std::size_t ir = 0; ir < cell_reynolds.size(); ++ir) {
        std::printf("  %6g", cell_reynolds[ir]);
        for (std::size_t ic = 0; ic < cfls.size(); ++ic) {
          const Outcome& o = map[{ir, ic}];
          const double dt = adaptive ? o.mean_dt : cfls[ic] * h / speed;
          const double d = speed * h / cell_reynolds[ir] * dt / (h * h);
          std::printf("   %c/%c%c", symbol(o.guarded), symbol(o.unguarded),
                      ab2_cn_max_amplification(cfls[ic], d) > 1.0 + 1e-12 ? '*' : ' ');
        }
        std::printf("\n");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
