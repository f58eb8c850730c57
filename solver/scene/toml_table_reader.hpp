// Typed, checked reads from one TOML table of a scene: each read rejects a wrong type or a value
// out of range with a one-line message naming file, place, key path and the allowed range
// (scene_diagnostics.hpp). Integers are accepted where a float is expected, never the reverse.
#pragma once
#include <array>
#include <climits>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "scene/scene_diagnostics.hpp"
#include "scene/scene_schema.hpp"

namespace ibms {

enum class Need { optional, required };

// Allowed interval for a floating-point value; NaN is never allowed, infinity only if asked.
struct Bounds {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_open = false;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_open = false;
  bool allow_infinity = false;

  bool contains(double value) const;
  std::string describe() const;  // "> 0", "in (0, 1]", "finite", ...
};

inline constexpr Bounds any_finite{};
inline constexpr Bounds positive{.lower = 0.0, .lower_open = true};
inline constexpr Bounds positive_or_infinite{.lower = 0.0, .lower_open = true, .allow_infinity = true};
inline constexpr Bounds non_negative{.lower = 0.0};
inline constexpr Bounds non_negative_or_infinite{.lower = 0.0, .allow_infinity = true};
inline constexpr Bounds unit_interval_open_closed{.lower = 0.0, .lower_open = true, .upper = 1.0};

// "integer", "floating-point number", "table", ... for messages.
std::string_view toml_type_name(toml::node_type type);

class TomlTableReader {
 public:
  // `table` may be null (section absent: optional keys keep defaults, required keys fail).
  TomlTableReader(const toml::table* table, std::string path, SceneDiagnostics& diagnostics)
      : table_(table), path_(std::move(path)), diagnostics_(&diagnostics) {}

  bool present() const { return table_ != nullptr; }
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;

  // Every key of the table must be in `allowed`; otherwise an error with a close match.
  void reject_unknown_keys(std::span<const std::string_view> allowed) const;
  // Every key must be in `allowed`, the keys of `owner` (e.g. "a body of kind 'rigid'"); a known
  // key of another variant fails with "does not belong to <owner> (its keys: ...)".
  void reject_keys_outside(std::span<const std::string_view> allowed, std::string_view owner) const;

  // Each read leaves `out` unchanged when the key is absent and optional; returns presence.
  bool read_real(std::string_view key, double& out, Need need, const Bounds& bounds) const;
  bool read_integer(std::string_view key, long& out, Need need, long lower,
                    long upper = LONG_MAX) const;
  bool read_integer(std::string_view key, int& out, Need need, long lower,
                    long upper = INT_MAX) const;
  // A number within bounds, or the string "auto" (out = auto_value).
  bool read_real_or_auto(std::string_view key, double& out, const Bounds& bounds, double auto_value) const;
  bool read_bool(std::string_view key, bool& out) const;
  bool read_string(std::string_view key, std::string& out) const;
  // A string naming one value of Enum (scene_schema.hpp: Choices<Enum>); any other string fails
  // with the allowed names and a close match.
  template <class Enum>
  bool read_choice(std::string_view key, Enum& out) const {
    std::size_t index = 0;
    if (!read_choice_index(key, index, scene_schema::choice_names<Enum>)) return false;
    out = scene_schema::Choices<Enum>::table[index].value;
    return true;
  }
  bool read_pair(std::string_view key, std::array<double, 2>& out, Need need) const;  // [a, b], finite
  // [[a, b], [c, d], ...], each pair finite; an empty array is allowed.
  bool read_pairs(std::string_view key, std::vector<std::array<double, 2>>& out) const;

  // The sub-table at `key` (absent: a reader over nothing); a non-table value is an error.
  TomlTableReader sub_table(std::string_view key) const;

  [[noreturn]] void fail(std::string_view key, const std::string& reason) const;

 private:
  // The position in `choices` of the string at `key`; false when the key is absent.
  bool read_choice_index(std::string_view key, std::size_t& index,
                         std::span<const std::string_view> choices) const;
  // The node at `key`, or null when absent (error if required); remembers its place.
  const toml::node* find(std::string_view key, Need need) const;
  [[noreturn]] void fail_type(std::string_view key, const toml::node& node,
                              std::string_view expected) const;

  const toml::table* table_;
  std::string path_;
  SceneDiagnostics* diagnostics_;
};

}  // namespace ibms
