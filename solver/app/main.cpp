// ibms command line (CLI11): `ibms run SCENE [--set key=value]... [-o FILE] [--restart FILE] [--quiet]`,
// `ibms info SCENE [--set key=value]...`, `ibms compare CASE FILE... [--validation-dir DIR]`
// (exit 0 pass, 1 fail, 2 bad input; docs/compare.md), `ibms --version` (one line: version and
// git commit, the same two values every output file records). Exit codes: 0 success, 2 bad input,
// 3 blow-up, 4 interrupted by SIGINT/SIGTERM (checkpoint written; continue with --restart), 1 other.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/compare.hpp"
#include "app/info.hpp"
#include "core/errors.hpp"
#include "fluid/fft_wisdom_cache.hpp"
#include "fluid/threads.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation_checkpoint.hpp"
#include "sim/simulation.hpp"


namespace {

constexpr int exit_interrupted = 4;

// Set by the SIGINT/SIGTERM handler to the signal number; the run loop checks it between steps,
// writes a checkpoint and stops. A second signal while stopping gets the default action
// (SA_RESETHAND); SA_RESTART keeps an HDF5 write in progress from failing with EINTR.
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void request_stop(int signal_number) { stop_signal = signal_number; }

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// The fluid guard's largest ratios over the run (sim/checks/fluid_guard.hpp): how close it came to a stop.
void print_fluid_guard(const ibms::Simulation& sim) {
  const ibms::FluidGuard& guard = sim.instability().fluid_guard;
  std::fprintf(stderr, "ibms: fluid guard: largest speed %.3g V_f (V_f = %.4g; stops above %g V_f), largest kinetic "
               "energy %.3g of its budget (stops above 1)\n", guard.largest_speed_ratio, guard.speed_scale,
               ibms::FluidGuard::speed_factor, guard.largest_energy_ratio);
}

// OpenMP reads its wait policy when its runtime loads, before main. libgomp's default waiter spins
// for about 300000 polls at every barrier: when the machine is busy it burns the core that the
// thread it waits for needs, and two threads ran a step up to ~80x slower than one
// (bench/bench_threads.sh). `ibms run` without a policy in its environment therefore starts itself
// again once with GOMP_SPINCOUNT=10000, which keeps the idle speed of the default spin and bounds the
// time a waiter burns; the ThreadGovernor (fluid/threads.hpp) then keeps the default count off a
// busy machine. If the new start fails the run goes on with the runtime's default.
void bounded_openmp_wait(int argc, char** argv) {
  if (!ibms::built_with_openmp() || argc < 2 || std::string(argv[1]) != "run") return;
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  setenv("GOMP_SPINCOUNT", "10000", 1);
  execv("/proc/self/exe", argv);
}

int run_command(const std::string& scene_path, const std::vector<std::string>& overrides,
                const std::string& output, const std::string& restart, bool quiet, bool govern_threads) {
  install_stop_handlers();  // first: a signal while the scene is read stops the run at step 0
  ibms::Scene scene = ibms::read_scene_file(scene_path, overrides);
  if (!output.empty()) scene.output.file = output;
  // The original run's FFTW plans before this run makes its own (bit-identical continuation);
  // a checkpoint that cannot be read is reported by run_simulation, which reads it again. A fresh
  // run of measured plans takes them from the machine's cache (fluid/fft_wisdom_cache.hpp); a
  // restart takes none from it, so that the checkpoint's plans are the ones FFTW finds.
  const bool measured = scene.run.fft_plans == ibms::RunSpec::FftPlans::measure;
  if (!restart.empty()) {
    try {
      ibms::import_checkpoint_planner_wisdom(ibms::read_checkpoint(restart));
    } catch (const ibms::InputError&) {
    }
  } else if (measured) {
    ibms::load_fft_wisdom_cache();
  }
  ibms::Simulation sim(scene);
  if (measured) ibms::save_fft_wisdom_cache();
  ibms::RunSummary summary;
  try {
    summary = ibms::run_simulation(sim, {scene.output.file, quiet, restart, &stop_signal, govern_threads});
  } catch (const ibms::BlowUpError&) {
    if (!quiet) print_fluid_guard(sim);
    throw;
  }
  if (!quiet) print_fluid_guard(sim);
  if (summary.interrupted) {
    std::fprintf(stderr, "ibms: %s at step %ld, t = %.6g; checkpoint written to %s (continue with --restart %s)\n",
                 summary.stop_reason.c_str(), summary.steps, summary.time, summary.output_path.c_str(),
                 summary.output_path.c_str());
    return exit_interrupted;
  }
  if (!quiet) {
    std::fprintf(stderr, "ibms: %ld steps to t = %.6g (%s) in %.2f s; output %s\n", summary.steps, summary.time,
                 summary.stop_reason.c_str(), summary.wall_seconds, summary.output_path.c_str());
    if (govern_threads)
      std::fprintf(stderr, "ibms: %d threads; %ld steps on one thread, where it was faster (busy machine)\n",
                   ibms::available_cores(), summary.steps_at_one_thread);
    std::fprintf(stderr, "%s", ibms::stage_timing_table(sim, summary.wall_seconds).c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bounded_openmp_wait(argc, argv);
  CLI::App app{"ibms: 2D incompressible flow with immersed deformable, swelling bodies"};
  app.set_version_flag("--version", std::string("ibms ") + ibms::ibms_version() + " (commit " + ibms::ibms_git_commit() + ")");
  app.require_subcommand(1);
  std::string scene_path, output, restart;
  std::vector<std::string> overrides;
  bool quiet = false;

  CLI::App* run = app.add_subcommand("run", "run a scene");
  run->add_option("scene", scene_path, "scene file (TOML)")->required();
  run->add_option("--set", overrides, "override a scene key: section.key=value (repeatable)");
  run->add_option("-o,--output", output, "HDF5 output file (default: output.file of the scene)");
  run->add_option("--restart", restart,
                  "continue from the /checkpoint of this ibms output file (same scene; [run] and [output] may "
                  "change); the output goes to a new file");
  run->add_flag("-q,--quiet", quiet, "no progress line");
  int threads = 0;
  run->add_option("--threads", threads,
                  "threads of the fluid's loops and FFTs (default 0: OMP_NUM_THREADS if set, else one per core "
                  "this process may use, with one thread for stretches of the run where it is faster); "
                  "the result does not depend on it");

  CLI::App* info = app.add_subcommand("info", "print the resolved scene, grid, stages and time-step limits");
  info->add_option("scene", scene_path, "scene file (TOML)")->required();
  info->add_option("--set", overrides, "override a scene key: section.key=value (repeatable)");

  std::string case_name, validation_dir;
  std::vector<std::string> compare_files;
  CLI::App* compare = app.add_subcommand("compare", "compare another code's CSV of a case's standard quantities "
                                                    "with the case's checks and ibms's own reference (docs/compare.md)");
  compare->add_option("case", case_name, "validation case (lid_driven_cavity_re100|re400|re1000, "
                                         "two_sided_cavity_re100, settling_disk, cavity_swelling_particles, "
                                         "cavity_deformable_objects)")->required();
  compare->add_option("files", compare_files, "CSV file(s): y,u and x,v profiles; t,v[,y] history; "
                                                "two body series (time,particle,...) or _bodies.csv")->required();
  compare->add_option("--validation-dir", validation_dir, "folder with <case>/reference/ (default: the source tree's "
                                                          "validation/ or $IBMS_VALIDATION_DIR)");

  CLI11_PARSE(app, argc, argv);
  try {
    if (run->parsed()) {
      // Before the Simulation plans its FFTs. An explicit count (--threads, OMP_NUM_THREADS) holds
      // for the whole run; the default, one thread per core this process may use, is governed
      // (fluid/threads.hpp: ThreadGovernor).
      const bool governed = threads <= 0 && std::getenv("OMP_NUM_THREADS") == nullptr;
      if (threads > 0) ibms::set_thread_count(threads);
      if (governed) {
        ibms::set_thread_count(ibms::available_cores());
        // The FFT plans split their work for all threads but are timed on one: timed on several, every
        // trial transform waits at barriers, which a busy machine stretches, and the plans timed on
        // one run as fast (bench/README.md, "Threads").
        ibms::set_loop_threads(1);
      }
      return run_command(scene_path, overrides, output, restart, quiet, governed && ibms::thread_count() > 1);
    }
    if (compare->parsed())
      return ibms::compare_case(case_name, compare_files,
                                validation_dir.empty() ? ibms::default_validation_dir() : validation_dir);
    if (info->parsed()) {
      const ibms::Scene scene = ibms::read_scene_file(scene_path, overrides);
      // describe_scene builds the run's Simulation: its plans as the run makes them.
      const bool measured = scene.run.fft_plans == ibms::RunSpec::FftPlans::measure;
      if (measured) ibms::load_fft_wisdom_cache();
      std::fputs(ibms::describe_scene(scene).c_str(), stdout);
      if (measured) ibms::save_fft_wisdom_cache();
      return 0;
    }
  } catch (const ibms::InputError& e) {
    std::fprintf(stderr, "ibms: error: %s\n", e.what());
    return 2;
  } catch (const ibms::BlowUpError& e) {
    std::fprintf(stderr, "ibms: run stopped: %s (output so far kept)\n", e.what());
    return 3;
  } catch (const ibms::OutputError& e) {
    std::fprintf(stderr, "ibms: output failed: %s\n", e.what());
    // A failed H5Fflush/H5Fclose leaves the file open inside HDF5 1.10, whose exit handler then
    // crashes closing it again (measured: SIGSEGV in H5F__close_cb under a file-size limit): leave
    // without the library's exit handlers, after flushing our own streams.
    std::fflush(nullptr);
    std::_Exit(5);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ibms: error: %s\n", e.what());
    return 1;
  }
  return 1;
}
