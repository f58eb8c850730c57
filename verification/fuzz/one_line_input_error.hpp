// The claim every libFuzzer target here tests: an input either gives its result or an InputError
// of one line (bad input gets ONE line); a multi-line InputError aborts, and any other exception
// escapes, so that libFuzzer reports either as a crash.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"

namespace ibms::fuzz {

// Runs run(); returns normally, or after an InputError of one line.
template <class Run>
void expect_result_or_one_line_input_error(Run&& run) {
  try {
    run();
  } catch (const InputError& error) {
    const std::string message = error.what();
    if (message.find('\n') != std::string::npos) {
      std::fprintf(stderr, "multi-line InputError: %s\n", message.c_str());
      std::abort();
    }
  }
}

}  // namespace ibms::fuzz
