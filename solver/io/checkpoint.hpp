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

 private:
  const Checkpoint& cp_;
  const std::string& path_;
};

}  // namespace ibms
