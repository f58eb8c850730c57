// Blow-up detection: non-finite values, a CFL number beyond run.max_cfl and a
// body point leaving the box are each reported by check_for_blow_up with step, time, quantity and
// place; run_simulation stops in the very step where a point leaves the box, and the series
// written before that step stay readable.
#define BOOST_TEST_MODULE blow_up
#include <boost/test/unit_test.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "scene/scene_reader.hpp"
#include "sim/checks/blow_up.hpp"
#include "sim/checks/fluid_guard.hpp"
#include "sim/time_step.hpp"
#include "sim/time_step_limits.hpp"
#include "sim/run/run.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path work_dir = fs::temp_directory_path() / ("ibms_blow_up_" + std::to_string(::getpid()));

// A wheel of diameter 0.2 just above the bottom wall of a unit box, thrown at it at 50 length/time;
// no contacts, and max_cfl raised so that only the box check can stop the run.
std::string wall_shot_scene() {
  return R"(# blow-up test scene, dimensionless
[run]
end_time = 0.1
time_step = 0.0002
max_cfl = 1000.0
[domain]
length_x = 1.0
length_y = 1.0
cells_x = 32
cells_y = 32
[fluid]
kinematic_viscosity = 0.01
[[bodies]]
centre = [0.5, 0.125]
diameter = 0.2
n_surface_points = 16
density = 2.0
spring_stiffness = 1000.0
velocity = [0.0, -50.0]
[output]
file = ")" + (work_dir / "wall_shot.h5").string() + R"("
progress = false
)";
}

ibms::Scene scene() {
  fs::create_directories(work_dir);
  return ibms::read_scene_string(wall_shot_scene(), "wall_shot.toml");
}

std::string blow_up_message(ibms::Simulation& sim, double dt) {
  try {
    ibms::check_for_blow_up(sim, dt, ibms::scan_velocity(sim.grid(), sim.fluid()));
  } catch (const ibms::BlowUpError& error) {
    return error.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Cleanup {
  ~Cleanup() { fs::remove_all(work_dir); }
} cleanup;

}  // namespace

BOOST_AUTO_TEST_CASE(non_finite_velocity_is_reported_with_step_time_and_cell) {
  ibms::Simulation sim(scene());
  ibms::start_fluid_guard(sim);  // as run_simulation does before the first step
  BOOST_TEST(blow_up_message(sim, 1e-4).empty());
  sim.fluid().step = 12;
  sim.fluid().time = 0.25;
  sim.fluid().velocity_y(5, 7) = std::numeric_limits<double>::quiet_NaN();
  const std::string message = blow_up_message(sim, 1e-4);
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(contains(message, "step 12, t = 0.25"), message);
  BOOST_TEST(contains(message, "non-finite velocity or pressure in cell (5, 7)"), message);
}

BOOST_AUTO_TEST_CASE(non_finite_pressure_is_reported) {
  ibms::Simulation sim(scene());
  sim.fluid().pressure(3, 2) = std::numeric_limits<double>::infinity();
  const std::string message = blow_up_message(sim, 1e-4);
  BOOST_TEST(contains(message, "non-finite velocity or pressure in cell (3, 2)"), message);
}

BOOST_AUTO_TEST_CASE(cfl_beyond_the_limit_is_reported_with_its_value_and_cell) {
  ibms::Simulation sim(scene());
  sim.fluid().velocity_x(20, 9) = 10.0;  // CFL = dt |u| / dx = dt 10 32
  ibms::start_fluid_guard(sim);  // the field set here is the initial one of the fluid guard's budget
  // max_cfl of this scene is 1000: use a dt that puts the CFL number just above it.
  const double dt = 1000.5 / (10.0 * 32.0);
  const std::string message = blow_up_message(sim, dt);
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(contains(message, "CFL number 1e+03 exceeds run.max_cfl = 1e+03 in cell (20, 9)"), message);
  BOOST_TEST(blow_up_message(sim, 999.5 / (10.0 * 32.0)).empty());
}

BOOST_AUTO_TEST_CASE(non_finite_body_point_is_reported_with_body_and_point) {
  ibms::Simulation sim(scene());
  sim.bodies()[0].velocity[4][0] = std::numeric_limits<double>::quiet_NaN();
  const std::string message = blow_up_message(sim, 1e-4);
  BOOST_TEST(contains(message, "body 0 point 4 is non-finite"), message);
}

BOOST_AUTO_TEST_CASE(run_stops_in_the_step_where_a_point_leaves_the_box) {
  const ibms::Scene s = scene();
  std::string message;
  {
    ibms::Simulation sim(s);
    try {
      ibms::run_simulation(sim, {s.output.file, /*quiet=*/true, "", nullptr});
    } catch (const ibms::BlowUpError& error) {
      message = error.what();
    }
  }
  BOOST_TEST_MESSAGE(message);
  BOOST_REQUIRE(contains(message, "left the box"));
  const long reported_step = std::stol(message.substr(message.find("step ") + 5));
  // Replay step by step: every point is inside after step reported_step - 1, one is not after it.
  ibms::Simulation replay(s);
  const auto all_inside = [&] {
    for (const auto& x : replay.bodies()[0].position)
      if (!(x[1] > 0.0 && x[1] < 1.0 && x[0] > 0.0 && x[0] < 1.0)) return false;
    return true;
  };
  for (long n = 1; n < reported_step; ++n) ibms::advance_one_step(replay, s.run.time_step);
  BOOST_TEST(all_inside());
  ibms::advance_one_step(replay, s.run.time_step);
  BOOST_TEST(!all_inside());
  // The output written before the blow-up is readable: one series row per completed step.
  const hid_t file = H5Fopen(s.output.file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  BOOST_REQUIRE(file >= 0);
  const hid_t dataset = H5Dopen2(file, "/series/step", H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  hsize_t rows = 0;
  H5Sget_simple_extent_dims(space, &rows, nullptr);
  H5Sclose(space);
  H5Dclose(dataset);
  H5Fclose(file);
  BOOST_TEST(rows == static_cast<hsize_t>(reported_step - 1));
}

// A rigid disk carried by a channel flow towards the outflow: the run stops, naming the
// body and the side, as soon as a rim point comes within 3 cells of the open side, before the
// kernel would reach across it.
BOOST_AUTO_TEST_CASE(body_reaching_an_outflow_stops_the_run_with_the_side_named) {
  fs::create_directories(work_dir);
  const ibms::Scene s = ibms::read_scene_string(R"(# channel, dimensionless
[run]
end_time = 2.0
[domain]
length_x = 2.0
length_y = 0.5
cells_x = 64
cells_y = 16
[fluid]
kinematic_viscosity = 0.01
[walls.left]
kind = "inflow"
velocity = 1.0
[walls.right]
kind = "outflow"
[[bodies]]
kind = "rigid"
centre = [1.6, 0.25]
diameter = 0.2
n_surface_points = 20
density = 1.0
[output]
file = ")" + (work_dir / "outflow.h5").string() + R"("
progress = false
)", "outflow.toml");
  std::string message;
  double rim_gap = 0.0;
  {
    ibms::Simulation sim(s);
    try {
      ibms::run_simulation(sim, {s.output.file, /*quiet=*/true, "", nullptr});
    } catch (const ibms::BlowUpError& error) {
      message = error.what();
      rim_gap = 2.0;
      for (const auto& x : sim.bodies()[0].position) rim_gap = std::min(rim_gap, 2.0 - x[0]);
    }
  }
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(contains(message, "right side (outflow)"), message);
  BOOST_TEST(contains(message, "body 0"), message);
  // Stopped in the step it came within 3 h = 0.09375, and not long after: the disk moves < h/2 per step.
  BOOST_TEST(rim_gap < 3 * 2.0 / 64);
  BOOST_TEST(rim_gap > 2 * 2.0 / 64);
}
