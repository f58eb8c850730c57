// Typed, checked reads from one TOML table of a scene (toml_table_reader.hpp).
#include "scene/toml_table_reader.hpp"

#include <cmath>

#include <fmt/format.h>

#include "scene/scene_schema.hpp"

namespace ibms {

bool Bounds::contains(double value) const {
  if (std::isnan(value)) return false;
  if (std::isinf(value) && !allow_infinity) return false;
  const bool above = lower_open ? value > lower : value >= lower;
  const bool below = upper_open ? value < upper : value <= upper;
  return above && below;
}

std::string Bounds::describe() const {
  const bool has_lower = std::isfinite(lower);
  const bool has_upper = std::isfinite(upper);
  std::string range;
  if (has_lower && has_upper) {
    range = fmt::format("in {}{}, {}{}", lower_open ? '(' : '[', lower, upper, upper_open ? ')' : ']');
  } else if (has_lower) {
    range = fmt::format("{} {}", lower_open ? ">" : ">=", lower);
  } else if (has_upper) {
    range = fmt::format("{} {}", upper_open ? "<" : "<=", upper);
  } else {
    return allow_infinity ? "a number (not nan)" : "finite";
  }
  return range + (allow_infinity ? " (inf allowed)" : " and finite");
}

std::string_view toml_type_name(toml::node_type type) {
  switch (type) {
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "floating-point number";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

std::string TomlTableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TomlTableReader::fail(std::string_view key, const std::string& reason) const {
  diagnostics_->fail(key_path(key), reason);
}

void TomlTableReader::fail_type(std::string_view key, const toml::node& node,
                                std::string_view expected) const {
  fail(key, fmt::format("expected {}, got {}", expected, toml_type_name(node.type())));
}

void TomlTableReader::reject_unknown_keys(std::span<const std::string_view> allowed) const {
  if (table_ == nullptr) return;
  for (auto&& [key, node] : *table_) {
    const std::string_view name = key.str();
    bool known = false;
    for (const std::string_view candidate : allowed) known = known || candidate == name;
    if (!known) {
      const std::string where = path_.empty() ? "the scene" : "[" + path_ + "]";
      diagnostics_->fail_at(key.source(), key_path(name),
                            fmt::format("unknown key in {}{} (allowed: {})", where,
                                        scene_schema::suggestion_suffix(name, allowed),
                                        scene_schema::join_names(allowed)));
    }
  }
}

void TomlTableReader::reject_keys_outside(std::span<const std::string_view> allowed,
                                          std::string_view owner) const {
  if (table_ == nullptr) return;
  for (auto&& [key, node] : *table_) {
    const std::string_view name = key.str();
    bool known = false;
    for (const std::string_view candidate : allowed) known = known || candidate == name;
    if (!known)
      diagnostics_->fail_at(key.source(), key_path(name),
                            fmt::format("does not belong to {} (its keys: {})", owner,
                                        scene_schema::join_names(allowed)));
  }
}

const toml::node* TomlTableReader::find(std::string_view key, Need need) const {
  const toml::node* node = table_ == nullptr ? nullptr : table_->get(key);
  if (node == nullptr) {
    if (need == Need::required) {
      const toml::source_region where = table_ == nullptr ? toml::source_region{} : table_->source();
      diagnostics_->fail_at(where, key_path(key),
                            table_ == nullptr ? fmt::format("required key missing (no [{}] section)", path_)
                                              : "required key missing");
    }
    return nullptr;
  }
  diagnostics_->remember(key_path(key), node->source());
  return node;
}

bool TomlTableReader::read_real(std::string_view key, double& out, Need need,
                                const Bounds& bounds) const {
  const toml::node* node = find(key, need);
  if (node == nullptr) return false;
  double value = 0.0;
  if (const auto* real = node->as_floating_point()) value = real->get();
  else if (const auto* integer = node->as_integer()) value = static_cast<double>(integer->get());
  else fail_type(key, *node, "a number");
  if (!bounds.contains(value)) fail(key, fmt::format("must be {}, got {}", bounds.describe(), value));
  out = value;
  return true;
}

bool TomlTableReader::read_integer(std::string_view key, long& out, Need need, long lower,
                                   long upper) const {
  const toml::node* node = find(key, need);
  if (node == nullptr) return false;
  const auto* integer = node->as_integer();
  if (integer == nullptr) fail_type(key, *node, "an integer");
  const std::int64_t value = integer->get();
  if (value < lower || value > upper) {
    fail(key, value < lower ? fmt::format("must be an integer >= {}, got {}", lower, value)
                            : fmt::format("must be an integer <= {}, got {}", upper, value));
  }
  out = static_cast<long>(value);
  return true;
}

bool TomlTableReader::read_integer(std::string_view key, int& out, Need need, long lower,
                                   long upper) const {
  long value = out;
  const bool found = read_integer(key, value, need, lower, std::min<long>(upper, INT_MAX));
  out = static_cast<int>(value);
  return found;
}

bool TomlTableReader::read_real_or_auto(std::string_view key, double& out, const Bounds& bounds,
                                        double auto_value) const {
  const toml::node* node = find(key, Need::optional);
  if (node == nullptr) return false;
  if (const auto* text = node->as_string()) {
    if (text->get() != "auto") fail(key, fmt::format("must be \"auto\" or a number {}, got '{}'", bounds.describe(), text->get()));
    out = auto_value;
    return true;
  }
  if (node->as_floating_point() == nullptr && node->as_integer() == nullptr)
    fail_type(key, *node, "\"auto\" or a number");
  return read_real(key, out, Need::optional, bounds);
}

bool TomlTableReader::read_bool(std::string_view key, bool& out) const {
  const toml::node* node = find(key, Need::optional);
  if (node == nullptr) return false;
  const auto* boolean = node->as_boolean();
  if (boolean == nullptr) fail_type(key, *node, "a boolean (true or false)");
  out = boolean->get();
  return true;
}

bool TomlTableReader::read_string(std::string_view key, std::string& out) const {
  const toml::node* node = find(key, Need::optional);
  if (node == nullptr) return false;
  const auto* text = node->as_string();
  if (text == nullptr) fail_type(key, *node, "a string");
  out = text->get();
  return true;
}

bool TomlTableReader::read_choice_index(std::string_view key, std::size_t& index,
                                        std::span<const std::string_view> choices) const {
  std::string value;
  if (!read_string(key, value)) return false;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (choices[k] == value) {
      index = k;
      return true;
    }
  }
  fail(key, fmt::format("must be one of {}, got '{}'{}", scene_schema::join_names(choices), value,
                        scene_schema::suggestion_suffix(value, choices)));
}

bool TomlTableReader::read_pair(std::string_view key, std::array<double, 2>& out, Need need) const {
  const toml::node* node = find(key, need);
  if (node == nullptr) return false;
  const auto* array = node->as_array();
  if (array == nullptr) fail_type(key, *node, "an array of two numbers [x, y]");
  if (array->size() != 2) {
    fail(key, fmt::format("expected an array of two numbers [x, y], got {} elements", array->size()));
  }
  std::array<double, 2> values{};
  for (std::size_t c = 0; c < 2; ++c) {
    const toml::node& element = *array->get(c);
    if (const auto* real = element.as_floating_point()) values[c] = real->get();
    else if (const auto* integer = element.as_integer()) values[c] = static_cast<double>(integer->get());
    else fail(key, fmt::format("element {} must be a number, got {}", c, toml_type_name(element.type())));
    if (!std::isfinite(values[c])) fail(key, fmt::format("element {} must be finite, got {}", c, values[c]));
  }
  out = values;
  return true;
}

bool TomlTableReader::read_pairs(std::string_view key, std::vector<std::array<double, 2>>& out) const {
  const toml::node* node = find(key, Need::optional);
  if (node == nullptr) return false;
  const auto* array = node->as_array();
  if (array == nullptr) fail_type(key, *node, "an array of points [[x, y], ...]");
  std::vector<std::array<double, 2>> values;
  for (std::size_t k = 0; k < array->size(); ++k) {
    const auto* pair = array->get(k)->as_array();
    if (pair == nullptr || pair->size() != 2)
      fail(key, fmt::format("element {} must be a point [x, y] of two numbers", k));
    std::array<double, 2> point{};
    for (std::size_t c = 0; c < 2; ++c) {
      const toml::node& element = *pair->get(c);
      if (const auto* real = element.as_floating_point()) point[c] = real->get();
      else if (const auto* integer = element.as_integer()) point[c] = static_cast<double>(integer->get());
      else fail(key, fmt::format("element {} component {} must be a number, got {}", k, c, toml_type_name(element.type())));
      if (!std::isfinite(point[c])) fail(key, fmt::format("element {} component {} must be finite", k, c));
    }
    values.push_back(point);
  }
  out = values;
  return true;
}

TomlTableReader TomlTableReader::sub_table(std::string_view key) const {
  const toml::node* node = find(key, Need::optional);
  if (node == nullptr) return {nullptr, key_path(key), *diagnostics_};
  const auto* table = node->as_table();
  if (table == nullptr) fail_type(key, *node, "a table");
  return {table, key_path(key), *diagnostics_};
}

}  // namespace ibms
