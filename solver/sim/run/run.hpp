// The run loop: steps until end_time, max_steps or the steady-state criterion, writing the
// HDF5 output (series, snapshots), the XDMF sidecar and the centre-line CSV files, with a
// progress line on stderr. A blow-up stops the run with BlowUpError after flushing the output.
// /checkpoint (simulation_checkpoint.hpp) is written every output.checkpoint_every steps, at the
// end, and when *stop_requested becomes non-zero (set by a SIGINT/SIGTERM handler; checked
// between steps). With restart_file the run first continues from that file's checkpoint.
#pragma once
#include <csignal>
#include <string>

#include "sim/run/run_output.hpp"  // ibms_version, stage_timing_table: what callers of the run print
#include "sim/simulation.hpp"

namespace ibms {

struct RunOptions {
  std::string output_path;   // HDF5 file; empty: scene.output.file
  bool quiet = false;        // no progress line
  std::string restart_file{};  // continue from this file's /checkpoint; empty: start at t = 0
  const volatile std::sig_atomic_t* stop_requested = nullptr;  // non-zero: checkpoint and stop
  bool govern_threads = false;  // the thread count is the default: a ThreadGovernor may use one thread
};

struct RunSummary {
  long steps = 0;
  double time = 0.0;
  bool reached_steady_state = false;
  std::string stop_reason;   // "end_time", "max_steps", "steady state", "interrupted by signal N"
  bool interrupted = false;  // stopped because *stop_requested was set (checkpoint written)
  double wall_seconds = 0.0;
  long steps_at_one_thread = 0;  // with govern_threads: the steps the governor ran on one thread
  std::string output_path;
};

RunSummary run_simulation(Simulation& sim, const RunOptions& options);

}  // namespace ibms
