// libFuzzer target on `ibms compare`'s readers: the input (fuzz_compare_input.hpp) names a case
// and holds the CSV files another code would give; the files are written to a scratch folder and
// read by compare_case and by the reference readers. The claim under test: every input gives a
// verdict or an InputError of one line; anything else (another exception, a crash, a sanitizer
// report) is a bug. Build: -DIBMS_FUZZ=ON with clang (scripts/run-fuzz.sh compare).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "fuzz_compare_input.hpp"
#include "one_line_input_error.hpp"

namespace {
std::string scratch_dir;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // compare_case prints its report on stdout: not wanted at millions of inputs.
  if (std::freopen("/dev/null", "w", stdout) == nullptr) std::abort();
  scratch_dir = (std::filesystem::temp_directory_path() / ("ibms_fuzz_compare_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(scratch_dir);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ibms::fuzz::expect_result_or_one_line_input_error([&] {
    ibms::fuzz::run_compare_input(ibms::fuzz::split_compare_input(text), scratch_dir, IBMS_FUZZ_VALIDATION_DIR);
  });
  return 0;
}
