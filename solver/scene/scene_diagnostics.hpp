// Error messages for scene input: every InputError from scene/ is ONE line,
//   "<file>:<line>:<col>: <key path>: <reason>"  where toml++ knows the place,
//   "<file>: <key path> (--set <text>): <reason>" for a value from a command-line override,
//   "<file>: <key path>: <reason>"               otherwise.
// The places of values read so far are remembered so cross-section checks can point at them.
#pragma once
#include <map>
#include <string>

#include <toml++/toml.h>

namespace ibms {

class SceneDiagnostics {
 public:
  explicit SceneDiagnostics(std::string source_name) : source_name_(std::move(source_name)) {}

  const std::string& source_name() const { return source_name_; }

  // `key_path` got its value from `--set <set_text>`.
  void note_override(const std::string& key_path, const std::string& set_text);
  // Where the value of `key_path` was written (used by fail()).
  void remember(const std::string& key_path, const toml::source_region& where);

  // Whether the scene text or a --set gave `key_path` a value (false: the default).
  bool was_given(const std::string& key_path) const {
    return places_.count(key_path) > 0 || override_texts_.count(key_path) > 0;
  }

  // Throw InputError about `key_path` at its remembered place (or the override, or no place).
  [[noreturn]] void fail(const std::string& key_path, const std::string& reason) const;
  // Throw InputError about `key_path` at `where`, unless the value came from an override.
  [[noreturn]] void fail_at(const toml::source_region& where, const std::string& key_path,
                            const std::string& reason) const;
  // Throw InputError "<file>: <subject>: <reason>" with no place.
  [[noreturn]] void fail_plain(const std::string& subject, const std::string& reason) const;

 private:
  std::string source_name_;
  std::map<std::string, std::string> override_texts_;   // key path -> "--set ..." text
  std::map<std::string, toml::source_region> places_;   // key path -> where it was read
};

// Text safe for a one-line message: control characters escaped, very long text shortened.
std::string one_line(std::string_view text, std::size_t max_length = 300);

}  // namespace ibms
