// The run loop writes the final step's series row even when output.series_every does not divide
// its step number, so a run's series always end at the state the run ended in (the body-cavity
// checks read "reached t_end" from the last row). A one-body scene with a fixed dt runs 7 steps
// with series_every = 3: rows at steps 3, 6 and the final 7, the last at t = end_time.
#define BOOST_TEST_MODULE final_series_row
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sim/run/run.hpp"
#include "sim_scenes.hpp"

using namespace ibms;

BOOST_AUTO_TEST_CASE(final_step_has_a_series_row) {
  std::string pattern = (std::filesystem::temp_directory_path() / "ibms_final_row_XXXXXX").string();
  const std::filesystem::path dir = mkdtemp(pattern.data());
  Scene scene = test::one_body_scene(/*n=*/32, /*periodic=*/true, /*diameter=*/0.25, /*density=*/1.5,
                                     /*stiffness=*/1e3);
  scene.run.time_step = 1e-3;
  scene.run.end_time = 7e-3;
  scene.output.series_every = 3;
  scene.output.progress = false;
  scene.output.centreline_profiles = false;
  Simulation sim(scene);
  const RunSummary summary = run_simulation(sim, {(dir / "out.h5").string(), /*quiet=*/true});
  std::ifstream in(dir / "out_bodies.csv");
  std::vector<double> times;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) { header = false; continue; }
    times.push_back(std::strtod(line.c_str(), nullptr));
  }
  std::filesystem::remove_all(dir);
  BOOST_TEST(summary.steps == 7);
  BOOST_REQUIRE(times.size() == 3u);
  BOOST_TEST(times[0] == 3e-3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(times[1] == 6e-3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(times[2] == 7e-3, boost::test_tools::tolerance(1e-12));
}
