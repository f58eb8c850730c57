// A run whose body goes unstable stops with a clear message instead of writing NaN (issue 5
// item 4): a stiff wheel advanced with one solid step per fluid step (fixed_solid_substeps = 1,
// dt far above its stable sub-step) through run_simulation throws BlowUpError naming step, time,
// body, point and position, and every value of the body series written up to then is finite.
// With the automatic sub-steps the same scene runs to its end, and so it does with
// spring_integrator = "auto", which takes the implicit spring step here (one sub-step per step).
#define BOOST_TEST_MODULE unstable_body_stops
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "../../validation/settling_disk/body_series.hpp"
#include "core/errors.hpp"
#include "sim/run.hpp"
#include "sim_scenes.hpp"
#include "solid/stable_substep.hpp"

using namespace ibms;

namespace {

Scene stiff_wheel_scene(const std::string& output) {
  Scene scene = test::one_body_scene(32, /*periodic=*/false, 0.25, 1.5, /*stiffness=*/1.0e6);
  scene.fluid.gravity = {0.0, -10.0};
  scene.run.time_step = 2.0e-3;
  scene.run.end_time = 0.04;
  scene.output.file = output;
  scene.output.progress = false;
  scene.output.centreline_profiles = false;
  scene.bodies[0].spring_integrator = "explicit";  // the implicit step has no stability limit
  return scene;
}

}  // namespace

BOOST_AUTO_TEST_CASE(fixed_step_instability_stops_with_message_and_no_nan_output) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ibms_test_unstable_body";
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "unstable.h5").string();
  Simulation sim(stiff_wheel_scene(out));
  // The fixed step is far beyond the stable one: 2e-3 against a spring sub-step of ~1e-5.
  BOOST_TEST(2.0e-3 > 10 * stable_substep(sim.bodies()[0], /*safety=*/1.0));
  sim.fixed_solid_substeps = 1;
  std::string message;
  try {
    run_simulation(sim, {out, /*quiet=*/true});
  } catch (const BlowUpError& e) {
    message = e.what();
  }
  BOOST_TEST_MESSAGE("stop message: " << message);
  BOOST_TEST(message.find("blow-up at step") != std::string::npos);
  BOOST_TEST(message.find("t = ") != std::string::npos);
  BOOST_TEST(message.find("body 0 point") != std::string::npos);
  const validation::SeriesTable series = validation::read_series_csv((dir / "unstable_bodies.csv").string());
  long values = 0, non_finite = 0;
  for (const auto& [name, column] : series)
    for (double v : column) { ++values; non_finite += !std::isfinite(v); }
  BOOST_TEST(values > 0);
  BOOST_TEST(non_finite == 0);
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(automatic_substeps_run_the_same_scene_to_its_end) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ibms_test_stable_body";
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "stable.h5").string();
  Simulation sim(stiff_wheel_scene(out));
  const RunSummary summary = run_simulation(sim, {out, /*quiet=*/true});
  BOOST_TEST(summary.stop_reason == "end_time");
  BOOST_TEST(sim.last_n_substeps > 1);
  Scene automatic = stiff_wheel_scene(out);
  automatic.bodies[0].spring_integrator = "auto";
  Simulation implicit(automatic);
  const RunSummary implicit_summary = run_simulation(implicit, {out, /*quiet=*/true});
  BOOST_TEST(implicit_summary.stop_reason == "end_time");
  BOOST_TEST(implicit.last_n_substeps == 1);
  std::filesystem::remove_all(dir);
}
