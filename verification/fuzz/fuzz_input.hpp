// The fuzz input format shared by the libFuzzer target (fuzz_scene.cpp) and the corpus replay
// test (test_fuzz_corpus.cpp): scene text, optionally preceded by lines "#set key=value" that
// become --set overrides (they are TOML comments, so the rest parses alike).
#pragma once
#include <string>
#include <vector>

namespace ibms::fuzz {

inline std::vector<std::string> leading_overrides(const std::string& text) {
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

}  // namespace ibms::fuzz
