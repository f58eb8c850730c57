// libFuzzer target on scene parsing and validation (issue 6 item 5): the input is scene text,
// optionally preceded by lines "#set key=value" that become --set overrides, fed to
// read_scene_string (TOML parse, overrides, typed reads, cross-section checks). The claim under
// test: every input either yields a Scene or throws InputError; anything else (another exception,
// a crash, a sanitizer report) is a bug. Build: -DIBMS_FUZZ=ON with clang (scripts/run-fuzz.sh).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "scene/scene_reader.hpp"

namespace {

// Leading "#set key=value" lines -> overrides (they are TOML comments, so the rest parses alike).
std::vector<std::string> leading_overrides(const std::string& text) {
  std::vector<std::string> overrides;
  std::size_t at = 0;
  const std::string marker = "#set ";
  while (text.compare(at, marker.size(), marker) == 0) {
    const std::size_t end = text.find('\n', at);
    const std::size_t stop = end == std::string::npos ? text.size() : end;
    overrides.push_back(text.substr(at + marker.size(), stop - at - marker.size()));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return overrides;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const ibms::Scene scene = ibms::read_scene_string(text, "fuzz.toml", leading_overrides(text));
    // The resolved text of an accepted scene must read back (resolved_scene_toml's contract).
    ibms::read_scene_string(scene.resolved_text, "fuzz_resolved.toml");
  } catch (const ibms::InputError& error) {
    const std::string message = error.what();
    if (message.find('\n') != std::string::npos) {  // bad input gets ONE line
      std::fprintf(stderr, "multi-line InputError: %s\n", message.c_str());
      std::abort();
    }
  }
  return 0;  // any other exception escapes and libFuzzer reports it as a crash
}
