// Error types: bad input (scene/command line) and numerical failure (blow-up) are distinct so
// the command line can report them differently and exit with distinct codes.
#pragma once
#include <stdexcept>
#include <string>

namespace ibms {

// Bad input: the message already names file, key and reason.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run that went wrong: the message names step, time, quantity and place.
struct BlowUpError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writing the output failed (disk full, file size limit, permission lost during the run): not bad
// input. The message names the file and the system's reason; no temporary file is left behind.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ibms
