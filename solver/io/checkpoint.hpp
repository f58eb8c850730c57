// Reading the restart state that OutputFile::write_checkpoint stored in /checkpoint
// (docs/design.md §5): named 1-D double arrays, double scalars, the format version, and the
// resolved scene text from the root attribute `scene`.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace ibms {

struct Checkpoint {
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, double> scalars;
  int format_version = 0;
  std::string scene;  // resolved scene TOML of the run that wrote it
};

// Throws InputError "<h5_path>: <reason>" when the file cannot be opened, has no /checkpoint,
// or the checkpoint is incomplete (the run was killed while writing it).
Checkpoint read_checkpoint(const std::string& h5_path);

}  // namespace ibms
