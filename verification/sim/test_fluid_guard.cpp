// The fluid guard (sim/checks/fluid_guard.hpp, docs/method.md §7): a slowly growing instability under the
// adaptive step, which the CFL guard cannot see, stops with the blow-up error naming step, time and
// quantity; a field that gains energy nothing feeds stops at the energy budget, or is reported once
// with run.on_fluid_instability = "warn"; stable runs are not stopped. The flow is the double shear
// layer of bench_fluid_stability (docs/fluid-stability.md §2) on 64^2 cells. A restart keeps the budget.
#define BOOST_TEST_MODULE fluid_guard
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "scene/scene_reader.hpp"
#include "sim/checks/blow_up.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/run/run.hpp"
#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "sim/run/simulation_checkpoint.hpp"

using namespace ibms;

namespace {

// One directory per process: two test runs on one machine (a clone's and a sanitizer build's) do not
// share the files.
const std::filesystem::path work_dir =
    std::filesystem::temp_directory_path() / ("ibms_test_fluid_guard_" + std::to_string(::getpid()));

// Doubly periodic unit box, U = 1, nu = h / Re_h, adaptive step at run.cfl (or a fixed step).
Scene shear_layer_scene(double cell_reynolds, double cfl, double time_step, double end_time) {
  std::filesystem::create_directories(work_dir);
  const std::string text =
      "[run]\nend_time = 1.0\n"
      "[domain]\nlength_x = 1.0\nlength_y = 1.0\ncells_x = 64\ncells_y = 64\nperiodic_x = true\nperiodic_y = true\n"
      "[output]\nprogress = false\ncentreline_profiles = false\n";
  return read_scene_string(text, "shear_layer (test_fluid_guard)",
                           {"fluid.kinematic_viscosity=" + std::to_string(1.0 / 64 / cell_reynolds),
                            "run.cfl=" + std::to_string(cfl), "run.time_step=" + std::to_string(time_step),
                            "run.end_time=" + std::to_string(end_time),
                            "output.file=\"" + (work_dir / "shear_layer.h5").string() + "\""});
}

// Bell, Colella & Glaz (1989): u = tanh((y - 1/4)/delta) below y = 1/2, tanh((3/4 - y)/delta)
// above, delta = 1/30, v = 0.05 sin(2 pi x) (bench/bench_fluid_stability.cpp).
void set_double_shear_layer(Simulation& sim) {
  const Grid& g = sim.grid();
  FluidState& f = sim.fluid();
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double y = g.y_centre(j);
      f.velocity_x(i, j) = y <= 0.5 ? std::tanh(30.0 * (y - 0.25)) : std::tanh(30.0 * (0.75 - y));
      f.velocity_y(i, j) = 0.05 * std::sin(2.0 * pi * g.x_centre(i));
    }
  sim.fluid_solver().initialise_faces(f);
}

// Runs the scene from the shear layer through run_simulation, with the blow-up message (empty if none).
struct GuardedRun {
  std::unique_ptr<Simulation> sim;
  std::string message;
};
GuardedRun run_shear_layer(const Scene& scene) {
  GuardedRun run{std::make_unique<Simulation>(scene), ""};
  set_double_shear_layer(*run.sim);
  try {
    run_simulation(*run.sim, {scene.output.file, /*quiet=*/true});
  } catch (const BlowUpError& e) {
    run.message = e.what();
  }
  return run;
}

// Steps with a fixed dt and multiplies the velocity by `gain` after each step: an energy source no
// scene has, growing E by gain^2 per step. Returns the message of the first stop, empty if none.
std::string run_with_gain(Simulation& sim, double gain, int steps) {
  for (int n = 0; n < steps; ++n) {
    const double dt = sim.scene().run.time_step;
    advance_one_step(sim, dt);
    FluidState& f = sim.fluid();
    for (int j = 0; j < sim.grid().ny; ++j)
      for (int i = 0; i < sim.grid().nx; ++i) {
        f.velocity_x(i, j) *= gain;
        f.velocity_y(i, j) *= gain;
      }
    try {
      check_for_blow_up(sim, dt, scan_velocity(sim.grid(), f));
    } catch (const BlowUpError& e) {
      return e.what();
    }
  }
  return "";
}

struct Cleanup {
  ~Cleanup() { std::filesystem::remove_all(work_dir); }
} cleanup;

}  // namespace

// Re_h = 512, run.cfl = 0.4: the slowest of the eight adaptive runs of docs/fluid-stability.md that
// ran to their end unstopped (CFL number below 0.9 throughout). The guard stops it when its largest
// speed passes 1.75 V_f, V_f = max |u^0| = 1.0.
BOOST_AUTO_TEST_CASE(slow_adaptive_instability_stops_naming_step_time_and_speed) {
  const GuardedRun run = run_shear_layer(shear_layer_scene(512, 0.4, 0.0, 10.0));
  const std::string& message = run.message;
  const Simulation* sim = run.sim.get();
  BOOST_TEST_MESSAGE("stop: " << message);
  BOOST_TEST(message.find("blow-up at step ") != std::string::npos);
  BOOST_TEST(message.find("fluid speed") != std::string::npos);
  BOOST_TEST(message.find("exceeds 1.75 V_f") != std::string::npos);
  BOOST_TEST(std::abs(sim->instability().fluid_guard.speed_scale - 1.0) < 0.01);  // max |u^0| = tanh(7.0) ~ 1, |v| <= 0.05
  BOOST_TEST(sim->fluid().time < 10.0);
}

// Re_h = 64, run.cfl = 0.5 is stable in the maps (largest speed 1.49 V_f over the maps' stable runs).
BOOST_AUTO_TEST_CASE(stable_adaptive_shear_layer_is_not_stopped) {
  const GuardedRun run = run_shear_layer(shear_layer_scene(64, 0.5, 0.0, 10.0));
  const std::string& message = run.message;
  const Simulation* sim = run.sim.get();
  BOOST_TEST(message.empty(), "stopped: " << message);
  BOOST_TEST_MESSAGE("largest speed " << sim->instability().fluid_guard.largest_speed_ratio << " V_f, energy "
                                      << sim->instability().fluid_guard.largest_energy_ratio << " of its budget");
  BOOST_TEST(sim->fluid().time == 10.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sim->instability().fluid_guard.largest_speed_ratio < FluidGuard::speed_factor);
}

// With nothing feeding it (periodic, no bodies: W = 0) the energy may not pass 1.02 E_0. A gain of
// 1.002 per step passes it within about 5 steps, far before the speed bound (1.75 = 1.002^280).
BOOST_AUTO_TEST_CASE(energy_gained_from_nothing_stops_at_the_budget) {
  Simulation sim(shear_layer_scene(512, 0.5, 0.25 / 64, 1.0));
  set_double_shear_layer(sim);
  start_fluid_guard(sim);
  const std::string message = run_with_gain(sim, 1.002, 100);
  BOOST_TEST_MESSAGE("stop: " << message);
  BOOST_TEST(message.find("fluid kinetic energy") != std::string::npos);
  BOOST_TEST(message.find("exceeds its budget") != std::string::npos);
  BOOST_TEST(sim.fluid().step <= 10);
  BOOST_TEST(sim.instability().fluid_guard.input_work == 0.0);
  // Without the gain the same steps stay within the budget.
  Simulation plain(shear_layer_scene(512, 0.5, 0.25 / 64, 1.0));
  set_double_shear_layer(plain);
  start_fluid_guard(plain);
  BOOST_TEST(run_with_gain(plain, 1.0, 100).empty());
}

// run.on_fluid_instability = "warn": the same run goes on, and the guard says so once.
BOOST_AUTO_TEST_CASE(warn_mode_reports_once_and_runs_on) {
  Scene scene = shear_layer_scene(512, 0.5, 0.25 / 64, 1.0);
  scene.run.on_fluid_instability = RunSpec::OnInstability::warn;
  Simulation sim(scene);
  set_double_shear_layer(sim);
  start_fluid_guard(sim);
  BOOST_TEST(run_with_gain(sim, 1.002, 30).empty());
  BOOST_TEST(sim.instability().fluid_guard.warned);
  BOOST_TEST(sim.fluid().step == 30);
}

// A lid-driven cavity from rest (Re 100, 32^2): the lid's work W feeds E; E stays within
// 1.5 W + floor and the speed within 1.75 U_lid.
BOOST_AUTO_TEST_CASE(driven_cavity_stays_within_the_wall_work) {
  std::filesystem::create_directories(work_dir);
  const Scene scene = read_scene_file(IBMS_CAVITY_SCENE, {"domain.cells_x=32", "domain.cells_y=32", "run.end_time=5",
                                                          "run.steady_tolerance=0", "output.progress=false",
                                                          "output.file=\"" + (work_dir / "cavity.h5").string() + "\""});
  Simulation sim(scene);
  run_simulation(sim, {scene.output.file, /*quiet=*/true});
  const VelocityScan scan = scan_velocity(sim.grid(), sim.fluid());
  BOOST_TEST_MESSAGE("E = " << scan.kinetic_energy << ", W = " << sim.instability().fluid_guard.input_work << ", largest speed "
                            << sim.instability().fluid_guard.largest_speed_ratio << " V_f, energy "
                            << sim.instability().fluid_guard.largest_energy_ratio << " of its budget");
  BOOST_TEST(sim.instability().fluid_guard.speed_scale == 1.0);  // the lid
  BOOST_TEST(sim.instability().fluid_guard.input_work > scan.kinetic_energy);  // the lid has done more work than E holds
  BOOST_TEST(sim.instability().fluid_guard.largest_energy_ratio < 1.0);
}

// The budget is part of the checkpoint: a run restarted from it goes on with the same V_f, E_0 and
// work W, not with a budget restarted from the restored field.
BOOST_AUTO_TEST_CASE(restart_keeps_the_budget) {
  std::filesystem::create_directories(work_dir);
  const std::string file = (work_dir / "cavity_restart.h5").string();
  const Scene scene = read_scene_file(IBMS_CAVITY_SCENE, {"domain.cells_x=16", "domain.cells_y=16", "run.end_time=1",
                                                          "run.steady_tolerance=0", "output.progress=false",
                                                          "output.file=\"" + file + "\""});
  Simulation sim(scene);
  run_simulation(sim, {file, /*quiet=*/true});
  Simulation restarted(scene);
  restore_simulation(read_checkpoint(file), file, restarted);
  BOOST_TEST(sim.instability().fluid_guard.input_work > 0.0);
  BOOST_TEST(restarted.instability().fluid_guard.input_work == sim.instability().fluid_guard.input_work);
  BOOST_TEST(restarted.instability().fluid_guard.initial_energy == sim.instability().fluid_guard.initial_energy);  // 0: from rest
  BOOST_TEST(restarted.instability().fluid_guard.speed_scale == sim.instability().fluid_guard.speed_scale);
  BOOST_TEST(restarted.instability().fluid_guard.boundary_power == sim.instability().fluid_guard.boundary_power);
}
