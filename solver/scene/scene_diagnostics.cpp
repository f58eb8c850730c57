// One-line scene error messages with file, line, column, key path and reason (scene_diagnostics.hpp).
#include "scene/scene_diagnostics.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace ibms {

std::string one_line(std::string_view text, std::size_t max_length) {
  std::string out;
  out.reserve(std::min(text.size(), max_length) + 8);
  for (const char c : text) {
    if (out.size() >= max_length) {
      out += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (byte < 0x20 || byte == 0x7f) out += fmt::format("\\x{:02x}", byte);
    else out += c;
  }
  return out;
}

void SceneDiagnostics::note_override(const std::string& key_path, const std::string& set_text) {
  override_texts_[key_path] = set_text;
}

void SceneDiagnostics::remember(const std::string& key_path, const toml::source_region& where) {
  places_[key_path] = where;
}

void SceneDiagnostics::fail(const std::string& key_path, const std::string& reason) const {
  const auto place = places_.find(key_path);
  fail_at(place == places_.end() ? toml::source_region{} : place->second, key_path, reason);
}

void SceneDiagnostics::fail_at(const toml::source_region& where, const std::string& key_path,
                               const std::string& reason) const {
  const auto over = override_texts_.find(key_path);
  if (over != override_texts_.end()) {
    throw InputError(fmt::format("{}: {} ({}): {}", one_line(source_name_), one_line(key_path),
                                 one_line(over->second), one_line(reason)));
  }
  if (where.begin.line > 0) {
    throw InputError(fmt::format("{}:{}:{}: {}: {}", one_line(source_name_), where.begin.line,
                                 where.begin.column, one_line(key_path), one_line(reason)));
  }
  fail_plain(key_path, reason);
}

void SceneDiagnostics::fail_plain(const std::string& subject, const std::string& reason) const {
  throw InputError(fmt::format("{}: {}: {}", one_line(source_name_), one_line(subject),
                               one_line(reason)));
}

}  // namespace ibms
