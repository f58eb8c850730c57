// The HDF5 output of one run (docs/design.md §5, the contract other implementations compare against):
//   /            attributes ibms_version, git_commit, scene (resolved TOML), start_time (ISO 8601 UTC), host
//   /grid        attributes nx, ny, length_x, length_y, origin_x, origin_y, periodic_x, periodic_y;
//                datasets dx, dy, x_centres (nx), y_centres (ny), x_faces (nx+1), y_faces (ny+1)
//   /series/*    extendable 1-D datasets, one row per append_series call (NaN where a row had no value)
//   /series/per_body/*  extendable 2-D datasets (rows, bodies), one per quantity of the bodies, the
//                same rows (attribute columns = "body index")
//   /snapshots/NNNNNN/*  (step, 6+ digits) attributes time, step; grid fields (ny, nx) x fastest,
//                the bodies' rim arrays bodies/<name> (all rim points, body after body), with
//                bodies/first_point (n_bodies + 1), bodies/body and the polygons bodies/topology
//   /checkpoint  the latest restart state (checkpoint.hpp)
// Every dataset has a `units` attribute. The file is flushed after each write, so a killed run
// leaves a readable file; /series rows are held back and written in blocks (series_block_rows rows,
// or series_block_seconds after the last block, and at every flush: snapshots, checkpoints, the
// end), so its series lag the run by at most one block. An XDMF sidecar (<path without .h5>.xmf)
// is rewritten after each snapshot.
#pragma once
#include <chrono>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "io/hdf5_handle.hpp"
#include "io/xdmf_sidecar.hpp"

namespace ibms {

struct SeriesValue {
  std::string name;   // may be a path, e.g. "body_000/centroid_x"
  std::string units;  // e.g. "length/time"
  double value;
};

// One quantity of every body in a series row: /series/per_body/<name>, one column per body.
struct SeriesColumns {
  std::string name;            // e.g. "centroid_x"
  std::string units;
  std::vector<double> values;  // one per body, NaN where a body has none
};

struct SnapshotArray {
  std::string name;               // e.g. "u" or "body_000/x"
  std::string units;
  std::vector<std::size_t> dims;  // (ny, nx) for grid fields, row-major x fastest; (n) for body arrays
  const double* data;             // product(dims) values
};

class OutputFile {
 public:
  // Creates (truncates) the file and writes the root attributes and /grid.
  // Throws InputError "<path>: <what>: <reason>" when the file cannot be created.
  OutputFile(const std::string& path, const std::string& resolved_scene, const Grid& grid,
             const std::string& version, const std::string& git_commit);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // One row of /series: each value into /series/<name> (created with its units on first use).
  // Series known from earlier rows but absent here get NaN in this row, so all series stay
  // aligned row by row. A name twice in one call is an error. The row reaches the file with its
  // block (see above). per_body: this row of /series/per_body/<name>; a quantity's column count is
  // fixed by its first row (another count is an error).
  void append_series(const std::vector<SeriesValue>& values, const std::vector<SeriesColumns>& per_body = {});
  static constexpr std::size_t series_block_rows = 256;
  static constexpr double series_block_seconds = 1.0;

  // /snapshots/NNNNNN with the arrays; then rewrites the XDMF sidecar. A step written twice,
  // an empty dims or a null data pointer is an error. body_points: the rim point count of each
  // body, when the arrays hold bodies/x and bodies/y of their sum (and other bodies/<name> of the
  // same length, node attributes in the sidecar): the snapshot gets bodies/first_point (each
  // body's first point, and the total), bodies/body (0, 1, ...) and bodies/topology, one polygon
  // per body in XDMF's Mixed form (3, n, the n point indices).
  void write_snapshot(long step, double time, const std::vector<SnapshotArray>& arrays,
                      const std::vector<std::size_t>& body_points = {});

  // Replaces /checkpoint: 1-D double datasets `arrays` (units "state"), double attributes
  // `scalars` (integers such as the step are stored as doubles, exact up to 2^53), attribute
  // format_version, and attribute complete = 1 once everything is written.
  void write_checkpoint(const std::map<std::string, std::vector<double>>& arrays,
                        const std::map<std::string, double>& scalars, int format_version);

  // Replaces /timing: one 1-element dataset per entry, /timing/<name> = seconds (units "s"), with
  // an integer attribute `calls` (docs/design.md §11: every output carries the wall seconds per stage).
  struct TimingEntry {
    std::string name;
    double seconds = 0.0;
    long calls = 0;
  };
  void write_timing(const std::vector<TimingEntry>& entries);

  void flush();  // the series rows held back, then H5Fflush; already called after each write
  const std::string& path() const { return path_; }
  const std::string& xdmf_path() const { return xdmf_path_; }

 private:
  void write_grid(const Grid& grid);
  hid_t series_dataset(const SeriesValue& value);
  struct Table {
    Hdf5Handle dataset;
    std::size_t width = 0;
    std::vector<double> pending;  // the rows held back, row-major
  };
  Table& series_table(const SeriesColumns& columns);
  void write_pending_series();  // the rows held back, into /series (no flush)

  std::string path_;
  std::string xdmf_path_;
  Grid grid_;
  Hdf5Handle file_;
  std::map<std::string, Hdf5Handle> series_;  // open /series datasets by name
  hsize_t n_series_rows_ = 0;                 // rows in the file
  std::size_t pending_rows_ = 0;                         // rows held back
  std::map<std::string, std::vector<double>> pending_;  // their values, one column per series
  std::map<std::string, Table> tables_;                 // /series/per_body datasets by name
  std::chrono::steady_clock::time_point last_series_block_ = std::chrono::steady_clock::now();
  std::vector<XdmfSnapshot> snapshots_;       // what the sidecar lists
};

}  // namespace ibms
