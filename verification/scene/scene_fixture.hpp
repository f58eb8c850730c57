// A valid scene (dimensionless cavity with two bodies, one swelling) that the scene tests
// modify one line at a time, and a replace helper that fails loudly if the edit misses.
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

namespace ibms::test {

inline std::string output_path() {
  return (std::filesystem::temp_directory_path() / "ibms_scene_test_out.h5").string();
}

inline std::string good_scene_text() {
  return R"(# test scene, dimensionless
[run]
end_time = 2.5
[domain]
length_x = 1.0
length_y = 1.0
cells_x = 32
cells_y = 32
[fluid]
kinematic_viscosity = 0.012345678901234567
gravity = [0.0, -1.0]
[walls.top]
speed = 1.0
[ibm]
kernel = "peskin4"
[[bodies]]
centre = [0.3, 0.5]
diameter = 0.2
n_surface_points = 32
density = 1.5
spring_stiffness = 100.0
[[bodies]]
centre = [0.7, 0.5]
diameter = 0.2
n_surface_points = 40
density = 1.5
spring_stiffness = 100
swelling = { onset_time = 0.1, rate = 0.05, max_diameter = 0.3 }
[contact]
stiffness = 1000.0
cds_radius_fraction = 0.1
[output]
file = ")" + output_path() + "\"\n";
}

// `text` with the first `from` replaced by `to`; throws if `from` is absent.
inline std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test fixture: '" + from + "' not in scene");
  return text.substr(0, at) + to + text.substr(at + from.size());
}

inline std::string good_scene_with(const std::string& from, const std::string& to) {
  return replaced(good_scene_text(), from, to);
}

}  // namespace ibms::test
