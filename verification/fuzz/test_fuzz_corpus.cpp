// Regression test of the scene fuzzer: every input kept in the fuzz corpus
// (seeds/: the validation scenes; corpus/: what the fuzzer found interesting) and every input that
// once crashed the reader (regressions/) is either accepted or refused with a one-line InputError
// naming the source; nothing else may escape read_scene_string. Same input format as
// fuzz_scene.cpp: leading "#set key=value" lines are overrides.
#define BOOST_TEST_MODULE fuzz_corpus
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "fuzz_input.hpp"
#include "scene/scene_reader.hpp"

namespace {

using ibms::fuzz::leading_overrides;

std::string file_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

struct Outcome {
  int accepted = 0, refused = 0;
};

// Reads every file under `dir`; each must be accepted or refused cleanly.
Outcome check_directory(const std::filesystem::path& dir) {
  Outcome outcome;
  if (!std::filesystem::is_directory(dir)) return outcome;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
    const std::string text = file_text(entry.path());
    BOOST_TEST_CONTEXT("input " << entry.path().filename().string()) {
      try {
        ibms::read_scene_string(text, "fuzz.toml", leading_overrides(text));
        ++outcome.accepted;
      } catch (const ibms::InputError& error) {
        const std::string message = error.what();
        BOOST_TEST(message.find("fuzz.toml") == 0u, message);
        BOOST_TEST(message.find('\n') == std::string::npos, "message is not one line");
        ++outcome.refused;
      } catch (const std::exception& error) {
        BOOST_ERROR("escaped exception: " << error.what());
      }
    }
  }
  return outcome;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_seed_is_a_valid_scene) {
  const Outcome outcome = check_directory(IBMS_FUZZ_SEED_DIR);
  BOOST_TEST_MESSAGE("seeds: " << outcome.accepted << " accepted, " << outcome.refused << " refused");
  BOOST_TEST(outcome.accepted >= 9);  // the 7 validation scenes and the 2 test scenes
  BOOST_TEST(outcome.refused == 0);
}

BOOST_AUTO_TEST_CASE(every_corpus_input_is_accepted_or_refused_with_one_line) {
  const Outcome outcome = check_directory(IBMS_FUZZ_CORPUS_DIR);
  BOOST_TEST_MESSAGE("corpus: " << outcome.accepted << " accepted, " << outcome.refused << " refused");
  BOOST_TEST(outcome.accepted + outcome.refused >= 100);  // the minimised corpus of the fuzz runs
}

BOOST_AUTO_TEST_CASE(every_former_crash_is_refused_or_accepted_cleanly) {
  const Outcome outcome = check_directory(IBMS_FUZZ_REGRESSION_DIR);
  BOOST_TEST_MESSAGE("regressions: " << outcome.accepted << " accepted, " << outcome.refused << " refused");
}
