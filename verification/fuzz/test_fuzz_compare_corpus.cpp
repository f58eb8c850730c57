// Regression test of the `ibms compare` fuzzer: every kept input (compare_seeds/: the shipped
// reference CSVs, trimmed, and the compare tests' bad inputs; compare_corpus/: what the fuzzer
// found interesting) and every input that once crashed a reader (compare_regressions/) gives a
// verdict (0 or 1) or an InputError of one line; nothing else escapes. Same input format as
// fuzz_compare.cpp (fuzz_compare_input.hpp).
#define BOOST_TEST_MODULE fuzz_compare_corpus
#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fuzz_compare_input.hpp"

namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// compare_case's report goes to stdout: silenced while it runs, so the test log stays readable.
struct SilentStdout {
  int saved;
  SilentStdout() {
    std::fflush(stdout);
    saved = ::dup(1);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::close(null);
  }
  ~SilentStdout() {
    std::fflush(stdout);
    ::dup2(saved, 1);
    ::close(saved);
  }
};

struct Outcome {
  int passed = 0, failed = 0, refused = 0;
};

Outcome check_directory(const fs::path& dir) {
  Outcome outcome;
  const fs::path scratch = fs::temp_directory_path() / ("ibms_fuzz_compare_corpus_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  if (fs::is_directory(dir))
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
      const std::string text = file_text(entry.path());
      BOOST_TEST_CONTEXT("input " << entry.path().filename().string()) {
        try {
          int verdict = 0;
          {
            SilentStdout silent;
            verdict = ibms::fuzz::run_compare_input(ibms::fuzz::split_compare_input(text), scratch.string(),
                                                    IBMS_FUZZ_VALIDATION_DIR);
          }
          BOOST_TEST((verdict == 0 || verdict == 1));
          ++(verdict == 0 ? outcome.passed : outcome.failed);
        } catch (const ibms::InputError& error) {
          const std::string message = error.what();
          BOOST_TEST(message.find('\n') == std::string::npos, "message is not one line: " << message);
          ++outcome.refused;
        } catch (const std::exception& error) {
          BOOST_ERROR("escaped exception: " << error.what());
        }
      }
    }
  fs::remove_all(scratch);
  return outcome;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_seed_gives_a_verdict_or_a_one_line_error) {
  const Outcome o = check_directory(IBMS_FUZZ_COMPARE_SEED_DIR);
  BOOST_TEST_MESSAGE("seeds: " << o.passed << " pass, " << o.failed << " fail, " << o.refused << " refused");
  BOOST_TEST(o.passed >= 1);   // the shipped references compared with themselves pass
  BOOST_TEST(o.refused >= 1);  // the compare tests' bad inputs are refused
}

BOOST_AUTO_TEST_CASE(every_corpus_input_gives_a_verdict_or_a_one_line_error) {
  const Outcome o = check_directory(IBMS_FUZZ_COMPARE_CORPUS_DIR);
  BOOST_TEST_MESSAGE("corpus: " << o.passed << " pass, " << o.failed << " fail, " << o.refused << " refused");
  BOOST_TEST(o.passed + o.failed + o.refused >= 300);  // the minimised corpus of the fuzz run (338 inputs)
}

BOOST_AUTO_TEST_CASE(every_former_crash_gives_a_verdict_or_a_one_line_error) {
  const Outcome o = check_directory(IBMS_FUZZ_COMPARE_REGRESSION_DIR);
  BOOST_TEST_MESSAGE("regressions: " << o.passed << " pass, " << o.failed << " fail, " << o.refused << " refused");
}
