// The run loop (docs/design.md §3 stage 6, §5): what happens between the steps, in order; what
// goes into the output is in sim/run/run_output.cpp.
#include "sim/run/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "core/errors.hpp"
#include "fluid/threads.hpp"
#include "io/checkpoint.hpp"
#include "sim/checks/control_volume_monitor.hpp"
#include "sim/time_step.hpp"
#include "sim/checks/blow_up.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "sim/run/run_output.hpp"
#include "sim/run/simulation_checkpoint.hpp"

namespace ibms {

RunSummary run_simulation(Simulation& sim, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const Scene& scene = sim.scene();
  const RunSpec& run = scene.run;
  RunSummary summary;
  summary.output_path = options.output_path.empty() ? scene.output.file : options.output_path;
  double next_snapshot = scene.output.snapshot_interval > 0 ? sim.fluid().time : HUGE_VAL;
  if (!options.restart_file.empty()) {  // before the output file exists: a bad restart writes nothing
    std::error_code error;
    if (std::filesystem::equivalent(options.restart_file, summary.output_path, error))
      throw InputError(options.restart_file + ": --restart: the output file would overwrite the checkpoint "
                       "being restarted from; give another output file with -o");
    next_snapshot = restore_simulation(read_checkpoint(options.restart_file), options.restart_file, sim);
  } else {
    start_fluid_guard(sim);  // from the field the run starts with (one set from C++ counts as initial)
  }
  RunOutput output(sim, summary.output_path);

  const auto start = clock::now();
  auto last_progress = start;
  const bool progress = scene.output.progress && !options.quiet;
  FluidState& f = sim.fluid();
  ControlVolumeMonitor control_volumes(sim);  // after the restore: it starts from the restored fields
  if (sim.has_bodies()) control_volumes.begin_step(sim);
  VelocityScan scan = scan_velocity(sim.grid(), f);
  const int full_count = thread_count();
  ThreadGovernor governor(options.govern_threads ? full_count : 1);
  set_loop_threads(governor.active() ? governor.count() : full_count);
  summary.stop_reason = "end_time";
  const double time_tolerance = 1e-12 * std::max(1.0, std::abs(run.end_time));
  try {
    if (!(next_time_step(sim, scan) > 0.0) && f.time < run.end_time)
      throw InputError(scene.source_file + ": run.max_time_step: the adaptive time step has no velocity scale "
                       "(fluid at rest, no moving wall): set run.max_time_step or run.time_step");
    while (f.time < run.end_time - time_tolerance) {
      if (run.max_steps > 0 && f.step >= run.max_steps) { summary.stop_reason = "max_steps"; break; }
      if (options.stop_requested != nullptr && *options.stop_requested != 0) {
        summary.interrupted = true;
        summary.stop_reason = fmt::format("interrupted by signal {}", static_cast<int>(*options.stop_requested));
        break;
      }
      if (f.time >= next_snapshot - time_tolerance) {
        output.snapshot(sim);
        next_snapshot += scene.output.snapshot_interval;
      }
      const double dt = next_time_step(sim, scan);
      const auto step_start = clock::now();
      advance_one_step(sim, dt);
      {
        auto t = sim.timers().time(Stage::diagnostics);
        scan = scan_velocity(sim.grid(), f);
        check_for_blow_up(sim, dt, scan);
        if (sim.has_bodies()) {  // the control-volume force of the step, and the start of the next one
          control_volumes.end_step(sim, dt);
          control_volumes.begin_step(sim);
        }
      }
      if (governor.active()) {
        set_loop_threads(governor.after_step(std::chrono::duration<double>(clock::now() - step_start).count()));
      }
      const ProjectionStats& ps = sim.stats().last_projection;
      const double steady_residual = ps.max_velocity > 0 ? ps.max_velocity_change / (dt * ps.max_velocity) : 0.0;
      output.end_step(sim, control_volumes, dt, dt * scan.max_rate, steady_residual);
      if (scene.output.checkpoint_every > 0 && f.step % scene.output.checkpoint_every == 0)
        output.checkpoint(sim, next_snapshot);
      if (run.steady_tolerance > 0 && steady_residual < run.steady_tolerance) {
        summary.reached_steady_state = true;
        summary.stop_reason = "steady state";
        break;
      }
      const auto now = clock::now();
      if (progress && now - last_progress > std::chrono::seconds(5)) {
        last_progress = now;
        print_progress(sim, std::chrono::duration<double>(now - start).count(), dt, steady_residual);
      }
    }
  } catch (const BlowUpError&) {
    set_loop_threads(full_count);
    output.after_blow_up(sim, std::chrono::duration<double>(clock::now() - start).count());
    throw;
  }
  output.finish(sim, control_volumes, next_snapshot);
  output.write_timing(sim, std::chrono::duration<double>(clock::now() - start).count());
  summary.steps = f.step;
  summary.time = f.time;
  summary.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  summary.steps_at_one_thread = governor.steps_at_one();
  set_loop_threads(full_count);
  return summary;
}

}  // namespace ibms
