// Every run's output carries /timing (docs/design.md §11): the wall seconds and calls
// of each pipeline stage and of the whole run, so a user sees where the time of their scene went.
#define BOOST_TEST_MODULE timing_output
#include <boost/test/unit_test.hpp>

#include <hdf5.h>

#include <filesystem>
#include <string>

#include "io/hdf5_handle.hpp"
#include "io/hdf5_objects.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
#include "core/stage_timers.hpp"

namespace {

double read_scalar(hid_t file, const std::string& path, long& calls) {
  const ibms::Hdf5Handle d = ibms::checked_handle(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose, "", path);
  double value = 0.0;
  H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value);
  calls = static_cast<long>(ibms::read_double_attribute(d.get(), "calls", ""));
  return value;
}

}  // namespace

BOOST_AUTO_TEST_CASE(run_output_carries_wall_seconds_and_calls_per_stage) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "ibms_timing_test.h5";
  const ibms::Scene scene = ibms::read_scene_file(IBMS_TIMING_SCENE, {"run.max_steps=12", "output.file=" + out.string()});
  ibms::Simulation sim(scene);
  const ibms::RunSummary summary = ibms::run_simulation(sim, {out.string(), /*quiet=*/true});
  const hid_t file = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  BOOST_TEST_REQUIRE(file >= 0);
  long calls = 0;
  const double run = read_scalar(file, "/timing/run", calls);
  BOOST_TEST(calls == summary.steps);
  double stages = 0.0;
  for (const auto& name : ibms::stage_names) {
    long stage_calls = 0;
    const double seconds = read_scalar(file, "/timing/" + std::string(name), stage_calls);
    BOOST_TEST_MESSAGE(name << ": " << seconds << " s in " << stage_calls << " calls");
    // What the run measured is what it wrote, and a stage that ran took time; one that did not, none.
    const auto stage = static_cast<ibms::Stage>(&name - ibms::stage_names.data());
    BOOST_TEST(seconds == sim.timers().seconds(stage));
    BOOST_TEST(stage_calls == sim.timers().calls(stage));
    BOOST_TEST((stage_calls > 0 ? seconds > 0.0 : seconds == 0.0));
    if (name != "contacts") stages += seconds;  // contacts run inside bodies
    // Every stage of this scene (bodies, contacts, output) runs at least once per step, except
    // output (series every step) which is also called at the end.
    if (name == "predictor" || name == "projection" || name == "bodies" || name == "ib_forcing")
      BOOST_TEST(stage_calls >= summary.steps);
  }
  BOOST_TEST(stages <= run * 1.001 + 1e-6);  // stages are inside the run's wall time
  // The solid sub-step totals, as the Simulation counted them (>= one per step; summed over the
  // bodies at least as many).
  long substeps = 0, body_substeps = 0;
  read_scalar(file, "/timing/solid_substeps", substeps);
  read_scalar(file, "/timing/body_substeps", body_substeps);
  BOOST_TEST(substeps == sim.stats().total_substeps);
  BOOST_TEST(body_substeps == sim.stats().total_body_substeps);
  BOOST_TEST(substeps >= summary.steps);
  BOOST_TEST(body_substeps >= substeps);
  // The printed table names every stage that ran and the totals.
  const std::string table = ibms::stage_timing_table(sim, summary.wall_seconds);
  for (const char* name : {"predictor", "projection", "bodies", "run", "solid sub-steps"})
    BOOST_TEST(table.find(name) != std::string::npos);
  H5Fclose(file);
  std::filesystem::remove(out);
}
