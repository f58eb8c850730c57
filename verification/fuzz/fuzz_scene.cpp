// libFuzzer target on scene parsing and validation: the input is scene text,
// optionally preceded by lines "#set key=value" that become --set overrides, fed to
// read_scene_string (TOML parse, overrides, typed reads, cross-section checks). The claim under
// test: every input either yields a Scene or throws InputError; anything else (another exception,
// a crash, a sanitizer report) is a bug. Build: -DIBMS_FUZZ=ON with clang (scripts/run-fuzz.sh).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "one_line_input_error.hpp"
#include "scene/scene_reader.hpp"

using ibms::fuzz::leading_overrides;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ibms::fuzz::expect_result_or_one_line_input_error([&] {
    const ibms::Scene scene = ibms::read_scene_string(text, "fuzz.toml", leading_overrides(text));
    // The resolved text of an accepted scene must read back (resolved_scene_toml's contract).
    ibms::read_scene_string(scene.resolved_text, "fuzz_resolved.toml");
  });
  return 0;
}
