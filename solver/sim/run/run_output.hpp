// What a run writes (docs/design.md §5): the HDF5 output file (series rows, snapshots, /checkpoint,
// /timing), the body table <stem>_bodies.csv and the centre-line profiles <stem>_centreline_*.csv,
// and the run's summaries on the terminal (the progress line, the stage timing table). The run
// loop (sim/run/run.cpp) says when; this says what goes in each.
#pragma once
#include <string>
#include <vector>

#include "io/output_file.hpp"
#include "sim/checks/control_volume_monitor.hpp"
#include "sim/simulation.hpp"

namespace ibms {

// The version and git commit this library was built from (what the output file records);
// ibms_git_commit() is in a source generated at every build (cmake/git_commit.cmake).
const char* ibms_version();
const char* ibms_git_commit();

// Body series kept in memory for <stem>_bodies.csv (one column per series, time first): the
// leading scalars, then body by body its quantities (body_NNN/<name>, those the body has), then the
// trailing scalars (separation, contacts, probes). The headers come from the first row.
struct BodyTable {
  std::vector<std::string> headers;
  std::vector<std::vector<double>> columns;
  // present[b * per_body.size() + q]: body b has quantity q.
  void append(double time, const std::vector<SeriesValue>& leading, const std::vector<SeriesColumns>& per_body,
              const std::vector<char>& present, const std::vector<SeriesValue>& trailing);
};

// The output of one run, opened before the first step. Each call is timed as Stage::output.
class RunOutput {
 public:
  // Creates h5_path with the scene's resolved text and the grid.
  RunOutput(const Simulation& sim, const std::string& h5_path);

  // /snapshots: u, v, p, vorticity and the rim points of every body at the current time.
  void snapshot(Simulation& sim);
  // After the step of length dt: the series row (and the body table's row) every
  // output.series_every steps; the step's figures are kept for finish.
  void end_step(Simulation& sim, const ControlVolumeMonitor& control_volumes, double dt, double cfl,
                double steady_residual);
  // /checkpoint (sim/run/simulation_checkpoint.hpp).
  void checkpoint(Simulation& sim, double next_snapshot);
  // The end of the run: the last step's series row unless written, the checkpoint, the last
  // snapshot, the centre-line profiles and the body table.
  void finish(Simulation& sim, const ControlVolumeMonitor& control_volumes, double next_snapshot);
  // /timing over wall_seconds of the run.
  void write_timing(const Simulation& sim, double wall_seconds);
  // A blow-up stops the run: the body table and /timing, and everything written so far stays readable.
  void after_blow_up(const Simulation& sim, double wall_seconds);

 private:
  std::string h5_path_;
  OutputFile file_;
  BodyTable body_table_;
  // The per-body quantities of a series row (/series/per_body) and which bodies have each.
  std::vector<SeriesColumns> per_body_;
  std::vector<char> present_;
  // The final step's series row is written even when output.series_every does not divide its step.
  long series_step_ = -1;
  double last_dt_ = 0.0, last_cfl_ = 0.0, last_residual_ = 0.0;
};

// The /timing figures as a table (stage, seconds, share of the wall time, calls; the solid
// sub-step totals): what `ibms run` prints at the end unless --quiet.
std::string stage_timing_table(const Simulation& sim, double wall_seconds);

// The progress line on stderr, elapsed_seconds into the run, after the step of length dt.
void print_progress(const Simulation& sim, double elapsed_seconds, double dt, double steady_residual);

}  // namespace ibms
