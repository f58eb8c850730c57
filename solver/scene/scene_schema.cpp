// Scene schema look-ups and misspelling suggestions (Levenshtein distance) for scene messages.
#include "scene/scene_schema.hpp"

#include <algorithm>
#include <vector>

namespace ibms::scene_schema {

std::span<const std::string_view> keys_of_section(std::string_view section) {
  if (section == "run") return run_keys;
  if (section == "domain") return domain_keys;
  if (section == "fluid") return fluid_keys;
  if (section == "ibm") return ibm_keys;
  if (section == "contact") return contact_keys;
  if (section == "output") return output_keys;
  return {};
}

std::span<const std::string_view> keys_of_side_kind(WallSpec::Kind kind) {
  switch (kind) {
    case WallSpec::Kind::wall: return wall_side_keys;
    case WallSpec::Kind::inflow: return inflow_side_keys;
    case WallSpec::Kind::outflow:
    case WallSpec::Kind::periodic: return open_side_keys;
  }
  return {};
}

std::span<const std::string_view> keys_of_body_kind(BodySpec::Kind kind) {
  switch (kind) {
    case BodySpec::Kind::mass_spring: return mass_spring_body_keys;
    case BodySpec::Kind::rigid: return rigid_body_keys;
    case BodySpec::Kind::prescribed: return prescribed_body_keys;
  }
  return {};
}

namespace {

// Edit distance (insertions, deletions, substitutions), O(|a| |b|) with one row.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_name(std::string_view name, std::span<const std::string_view> allowed) {
  // A fuzzed key may be huge; misspellings of our keys are short.
  if (name.size() > 64) return {};
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const std::string_view candidate : allowed) {
    const std::size_t distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = std::string(candidate);
    }
  }
  return best;
}

std::string suggestion_suffix(std::string_view name, std::span<const std::string_view> allowed) {
  const std::string best = closest_name(name, allowed);
  return best.empty() ? std::string{} : ", did you mean '" + best + "'?";
}

std::string join_names(std::span<const std::string_view> names) {
  std::string out;
  for (const std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

}  // namespace ibms::scene_schema
