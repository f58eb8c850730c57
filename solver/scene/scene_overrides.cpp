// Command-line overrides of scene keys (scene_overrides.hpp). The key is checked against the
// schema (scene_schema.hpp) before the tree is touched; missing tables on the way are created,
// so overriding a key absent from the file is allowed.
#include "scene/scene_overrides.hpp"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "scene/scene_schema.hpp"

namespace ibms {

namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_dotted(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.emplace_back(key.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

bool contains(std::span<const std::string_view> names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A one-key table {v = <text>} with <text> read as a TOML value; anything else becomes a string.
toml::table parse_override_value(std::string_view text) {
  try {
    const std::string document = "v = " + std::string(text) + "\n";
    toml::table parsed = toml::parse(std::string_view(document), std::string_view("--set"));
    if (parsed.size() == 1 && parsed.contains("v")) return parsed;
  } catch (const toml::parse_error&) {
    // Not a TOML value: fall through to a plain string (e.g. output.file=run/out.h5).
  }
  return toml::table{{"v", std::string(text)}};
}

class OverrideApplier {
 public:
  OverrideApplier(toml::table& root, SceneDiagnostics& diagnostics, std::string set_text)
      : root_(root), diagnostics_(diagnostics), set_text_(std::move(set_text)) {}

  void apply() {
    const auto equals = set_text_.find('=');
    if (equals == std::string::npos) fail("expected key=value");
    const std::string_view key = trim(std::string_view(set_text_).substr(0, equals));
    const std::vector<std::string> parts = split_dotted(key);
    if (std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); })) {
      fail(fmt::format("malformed key '{}'", key));
    }
    toml::table& parent = parent_table(parts);
    toml::table value = parse_override_value(trim(std::string_view(set_text_).substr(equals + 1)));
    parent.insert_or_assign(parts.back(), std::move(*value.get("v")));
    diagnostics_.note_override(std::string(key), "--set " + set_text_);
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    diagnostics_.fail_plain("--set " + set_text_, reason);
  }

  void require_key(std::string_view name, std::span<const std::string_view> allowed,
                   std::string_view where) const {
    if (!contains(allowed, name)) {
      fail(fmt::format("unknown key '{}' in {}{}", name, where,
                       scene_schema::suggestion_suffix(name, allowed)));
    }
  }

  // The table under `parent` named `name`, created if absent.
  toml::table& child_table(toml::table& parent, std::string_view name, std::string_view path) const {
    if (!parent.contains(name)) parent.insert(name, toml::table{});
    toml::table* table = parent.get(name)->as_table();
    if (table == nullptr) fail(fmt::format("'{}' in the scene is not a table", path));
    return *table;
  }

  // Checks the key path against the schema and returns the table that holds its last part.
  toml::table& parent_table(const std::vector<std::string>& parts) const {
    const std::string& section = parts[0];
    require_key(section, scene_schema::section_names, "the scene");
    if (section == "walls") {
      if (parts.size() != 3) fail("expected walls.<left|right|bottom|top>.<key>");
      require_key(parts[1], scene_schema::wall_names, "[walls]");
      require_key(parts[2], scene_schema::wall_keys, "[walls." + parts[1] + "]");
      return child_table(child_table(root_, "walls", "walls"), parts[1], "walls." + parts[1]);
    }
    if (section == "bodies") return body_table(parts);
    if (parts.size() != 2) fail(fmt::format("expected {}.<key>", section));
    require_key(parts[1], scene_schema::keys_of_section(section), "[" + section + "]");
    return child_table(root_, section, section);
  }

  toml::table& body_table(const std::vector<std::string>& parts) const {
    const bool is_swelling = parts.size() == 4 && parts[2] == "swelling";
    if (parts.size() != 3 && !is_swelling) {
      fail("expected bodies.<index>.<key> or bodies.<index>.swelling.<key>");
    }
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(parts[1].data(), parts[1].data() + parts[1].size(), index);
    if (error != std::errc{} || end != parts[1].data() + parts[1].size()) {
      fail(fmt::format("body index '{}' is not a non-negative integer", parts[1]));
    }
    toml::node* bodies_node = root_.get("bodies");
    toml::array* bodies = bodies_node == nullptr ? nullptr : bodies_node->as_array();
    const std::size_t n_bodies = bodies == nullptr ? 0 : bodies->size();
    if (index >= n_bodies) {
      fail(fmt::format("no body {}: the scene has {} [[bodies]] entries", index, n_bodies));
    }
    toml::table* body = bodies->get(index)->as_table();
    if (body == nullptr) fail(fmt::format("bodies[{}] in the scene is not a table", index));
    if (!is_swelling) {
      require_key(parts[2], scene_schema::body_keys, "[[bodies]]");
      if (parts[2] == "swelling") fail("expected bodies.<index>.swelling.<key>");
      return *body;
    }
    require_key(parts[3], scene_schema::swelling_keys, "bodies.swelling");
    return child_table(*body, "swelling", fmt::format("bodies.{}.swelling", index));
  }

  toml::table& root_;
  SceneDiagnostics& diagnostics_;
  std::string set_text_;
};

}  // namespace

void apply_scene_overrides(toml::table& root, const std::vector<std::string>& overrides,
                           SceneDiagnostics& diagnostics) {
  for (const std::string& text : overrides) OverrideApplier(root, diagnostics, text).apply();
}

}  // namespace ibms
