// Reading the restart state that OutputFile::write_checkpoint stored in /checkpoint
// (docs/design.md §5): named 1-D double arrays, double scalars, the format version, and the
// resolved scene text from the root attribute `scene`.
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/fields.hpp"

namespace ibms {

using Vec2 = std::array<double, 2>;

struct Checkpoint {
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, double> scalars;
  int format_version = 0;
  std::string scene;  // resolved scene TOML of the run that wrote it
};

// Throws InputError "<h5_path>: <reason>" when the file cannot be opened, has no /checkpoint,
// or the checkpoint is incomplete (the run was killed while writing it).
Checkpoint read_checkpoint(const std::string& h5_path);

// Per-body arrays of one kind in one dataset, so that a thousand bodies are a few datasets: body b's
// values follow body b-1's in <name>, and <name>_count holds each body's value count. Called for
// bodies 0, 1, ... in turn (a body without such values appends none); out of order is a logic_error.
void append_body_array(std::map<std::string, std::vector<double>>& arrays, const std::string& name, std::size_t body,
                       const std::vector<double>& values);

// One body's values in a per-body array.
struct BodySlice {
  const double* data = nullptr;
  std::size_t size = 0;
};

// Named arrays and scalars of a checkpoint, each failure an InputError
// "<path>: /checkpoint/<name>: <reason>".
class CheckpointReader {
 public:
  CheckpointReader(const Checkpoint& checkpoint, const std::string& path) : cp_(checkpoint), path_(path) {}

  [[noreturn]] void fail(const std::string& name, const std::string& reason) const;
  double scalar(const std::string& name) const;
  // A scalar that must be finite and >= 0 (time, dt^{n-1}).
  double non_negative(const std::string& name) const;
  // A count stored as a double: a whole number in [0, 2^53] (exact in a double; no overflow on the cast).
  long count(const std::string& name) const;
  // An array of exactly expected_size values.
  const std::vector<double>& array(const std::string& name, std::size_t expected_size) const;
  // An array of any size (empty when absent).
  const std::vector<double>* find(const std::string& name) const;
  void into(const std::string& name, CellField& field) const;
  void into(const std::string& name, FaceField& field) const;
  void into(const std::string& name, std::vector<Vec2>& points) const;
  void into(const std::string& name, std::vector<double>& values) const;
  // Body b's values of the per-body array `name` (append_body_array) among n_bodies: checks that
  // the counts are n_bodies whole numbers adding up to the values.
  BodySlice body_array(const std::string& name, std::size_t body, std::size_t n_bodies) const;
  // The same with exactly expected_size values.
  BodySlice body_array(const std::string& name, std::size_t body, std::size_t n_bodies, std::size_t expected_size) const;

 private:
  const Checkpoint& cp_;
  const std::string& path_;
  mutable std::map<std::string, std::vector<std::size_t>> offsets_;  // per-body arrays checked once
};

}  // namespace ibms
