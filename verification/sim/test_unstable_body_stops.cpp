// A run whose body goes unstable stops with a clear message instead of writing NaN: a
// stiff wheel advanced with one solid step per fluid step (Simulation::set_fixed_substeps(1),
// dt far above its stable sub-step) through run_simulation throws BlowUpError naming step, time and
// body (a point that left the box, or the body's kinetic energy against the bound the scene can give
// it, whichever guard sees the blow-up first), and every value of the body series written up to then
// is finite.
// With the automatic sub-steps the same scene runs to its end, and so it does with
// spring_integrator = "auto", which takes the implicit spring step here (one sub-step per step).
#define BOOST_TEST_MODULE unstable_body_stops
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "metrics/body_series.hpp"
#include "core/errors.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
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
  // The implicit step has no stability limit.
  scene.bodies[0].spring_integrator = BodySpec::SpringIntegrator::explicit_euler;
  return scene;
}

// Runs with one solid step per fluid step; the blow-up message, empty if the run reached its end.
std::string message_of_fixed_step_run(Simulation& sim, const std::string& out) {
  sim.set_fixed_substeps(1);
  std::string message;
  try {
    run_simulation(sim, {out, /*quiet=*/true});
  } catch (const BlowUpError& e) {
    message = e.what();
  }
  BOOST_TEST_MESSAGE("stop message: " << message);
  return message;
}

}  // namespace

BOOST_AUTO_TEST_CASE(fixed_step_instability_stops_with_message_and_no_nan_output) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ibms_test_unstable_body";
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "unstable.h5").string();
  Simulation sim(stiff_wheel_scene(out));
  // The fixed step is far beyond the stable one: 2e-3 against a spring sub-step of ~1e-5.
  BOOST_TEST(2.0e-3 > 10 * stable_substep(sim.bodies()[0], /*safety=*/1.0));
  const std::string message = message_of_fixed_step_run(sim, out);
  BOOST_TEST(message.find("blow-up at step") != std::string::npos);
  BOOST_TEST(message.find("t = ") != std::string::npos);
  BOOST_TEST((message.find("body 0 point") != std::string::npos ||
              message.find("body 0 has kinetic energy") != std::string::npos));
  const SeriesTable series = read_series_csv((dir / "unstable_bodies.csv").string());
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
  BOOST_TEST(sim.stats().last_n_substeps > 1);
  Scene automatic = stiff_wheel_scene(out);
  automatic.bodies[0].spring_integrator = BodySpec::SpringIntegrator::automatic;
  Simulation implicit(automatic);
  const RunSummary implicit_summary = run_simulation(implicit, {out, /*quiet=*/true});
  BOOST_TEST(implicit_summary.stop_reason == "end_time");
  BOOST_TEST(implicit.stats().last_n_substeps == 1);
  std::filesystem::remove_all(dir);
}

// The instability guard on the collision of bench_stability that an unguarded run takes to its
// end unflagged: two wheels approaching at 5 cm/s each, contact stiffness 1e3, fluid step
// 3e-3 s with one explicit solid step per fluid step. The contact returns more energy than it
// received (restitution > 1): the run stops naming it; with run.on_body_instability = "warn" it
// goes on; with automatic sub-steps the contact work stays <= 0 up to its integration error.
namespace {

Scene collision_scene(double dem_stiffness, double dt) {
  // The papers' coupling, where the fixed single sub-step pumps energy through the contact (the
  // settling scene ships the end-of-step constraint, whose rim response in the marker system holds it).
  Scene s = read_scene_file(IBMS_SETTLING_SCENE,
                            {"ibm.coupling=uhlmann", "ibm.marker_retraction=0", "domain.length_y=1.0", "domain.cells_x=40", "domain.cells_y=20", "bodies.0.centre=[0.85, 0.5]",
                             "bodies.0.density=2.0",
                             "bodies.0.n_surface_points=16", "fluid.gravity=[0.0, 0.0]", "run.end_time=0.08",
                             "run.time_step=" + std::to_string(dt), "contact.stiffness=" + std::to_string(dem_stiffness),
                             "contact.restitution_coefficient=0.9", "contact.cds_radius_fraction=0.05",
                             "bodies.0.spring_stiffness=100", "bodies.0.spring_integrator=explicit", "output.progress=false",
                             "output.centreline_profiles=false"});
  s.bodies.push_back(s.bodies[0]);
  s.bodies[0].centre = {0.85, 0.5};
  s.bodies[0].velocity = {5.0, 0.0};
  s.bodies[1].centre = {1.15, 0.5};
  s.bodies[1].velocity = {-5.0, 0.0};
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_contact_returning_more_energy_than_it_received_stops_the_run) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ibms_test_contact_guard";
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "guard.h5").string();
  {
    Simulation sim(collision_scene(1e3, 3e-3));
    BOOST_TEST(message_of_fixed_step_run(sim, out).find("the contacts have returned") != std::string::npos);
  }
  {
    Scene scene = collision_scene(1e3, 3e-3);
    scene.run.on_body_instability = RunSpec::OnInstability::warn;
    Simulation sim(scene);
    sim.set_fixed_substeps(1);
    BOOST_TEST(run_simulation(sim, {out, /*quiet=*/true}).stop_reason == "end_time");
    BOOST_TEST(sim.instability().warned);
  }
  {
    Simulation sim(collision_scene(1e3, 3e-3));
    const RunSummary summary = run_simulation(sim, {out, /*quiet=*/true});
    BOOST_TEST(summary.stop_reason == "end_time");
    BOOST_TEST(sim.stats().total_contact_work < 0.0);  // they met, and the contact (e = 0.9) took energy
    BOOST_TEST(!sim.instability().warned);
  }
  std::filesystem::remove_all(dir);
}

// A contact deeper than the contact spheres stops the run: the two wheels of restart_scene under the
// collision-time law at CFL 0.1 with no step cap (dt ~ 0.02, T_c = 10 dt ~ 0.2; a wheel at 0.8
// overlaps ~ v0 T_c / pi ~ 0.05 > the CDS radius 0.02), with the overlap and both keys named. The
// run is given until t = 4, so that the step at the contact (t ~ 0.76) is the CFL step and not the
// end approach's plan (docs/method.md §7), which would hold the step of t ~ 0.1 to the end. The
// same scene at its own fixed step 0.004 (T_c = 0.04) runs to its end with every overlap below the radius.
BOOST_AUTO_TEST_CASE(a_contact_deeper_than_its_spheres_stops_the_run) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ibms_test_contact_overlap";
  std::filesystem::create_directories(dir);
  const std::vector<std::string> collision_time{"contact.model=\"collision_time\"", "contact.stiffness=0"};
  std::vector<std::string> uncapped = collision_time;
  uncapped.insert(uncapped.end(), {"run.time_step=0", "run.cfl=0.1", "run.max_time_step=1", "run.end_time=4"});
  Scene deep = read_scene_file(IBMS_RESTART_SCENE, uncapped);
  deep.output.file = (dir / "deep.h5").string();
  Simulation sim(deep);
  std::string message;
  try {
    run_simulation(sim, {deep.output.file, /*quiet=*/true});
  } catch (const BlowUpError& e) {
    message = e.what();
  }
  BOOST_TEST_MESSAGE("stop message: " << message);
  BOOST_TEST(message.find("contact overlap of") != std::string::npos);
  BOOST_TEST(message.find("contact.collision_steps") != std::string::npos);
  BOOST_TEST(message.find("run.max_time_step") != std::string::npos);
  BOOST_TEST(sim.stats().last_contact_stats.max_overlap > sim.contact_model().cds_radius_of(sim.bodies()[0]));

  Scene shallow = read_scene_file(IBMS_RESTART_SCENE, collision_time);
  shallow.output.file = (dir / "shallow.h5").string();
  Simulation fine(shallow);
  BOOST_CHECK_NO_THROW(run_simulation(fine, {shallow.output.file, /*quiet=*/true}));
  BOOST_TEST(fine.fluid().time == shallow.run.end_time, boost::test_tools::tolerance(1e-12));
}
