// The run loop: steps until end_time, max_steps or the steady-state criterion, writing the
// HDF5 output (series, snapshots), the XDMF sidecar and the centre-line CSV files, with a
// progress line on stderr. A blow-up stops the run with BlowUpError after flushing the output.
#pragma once
#include <string>

#include "sim/simulation.hpp"

namespace ibms {

struct RunOptions {
  std::string output_path;   // HDF5 file; empty: scene.output.file
  bool quiet = false;        // no progress line
};

struct RunSummary {
  long steps = 0;
  double time = 0.0;
  bool reached_steady_state = false;
  std::string stop_reason;   // "end_time", "max_steps", "steady state"
  double wall_seconds = 0.0;
  std::string output_path;
};

RunSummary run_simulation(Simulation& sim, const RunOptions& options);

}  // namespace ibms
