// A scene pays only for what it uses (docs/design.md §3), structurally: the pipeline of
// a fluid-only scene holds no body stage and its timers record no body work; a one-body scene with
// contacts evaluates wall contacts but lists no pair search and examines no CDS pair; two bodies do.
// (The per-step cost figures are measured by bench/bench_overhead.cpp, not asserted here.)
#define BOOST_TEST_MODULE stage_structure
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <string>

#include "sim/simulation.hpp"
#include "sim/time_step.hpp"
#include "sim_scenes.hpp"

using namespace ibms;

namespace {

bool lists_stage(const Simulation& sim, const std::string& word) {
  const std::vector<std::string> stages = sim.stage_names();
  return std::any_of(stages.begin(), stages.end(), [&](const std::string& s) { return s.find(word) != std::string::npos; });
}

Scene with_contacts(Scene scene) {
  scene.contact.stiffness = 1.0e4;
  scene.contact.restitution_coefficient = 0.5;
  scene.contact.cds_radius_fraction = 0.05;
  return scene;
}

void run_steps(Simulation& sim, int n, double dt) {
  for (int k = 0; k < n; ++k) advance_one_step(sim, dt);
}

}  // namespace

BOOST_AUTO_TEST_CASE(fluid_only_scene_runs_no_body_stage) {
  Scene scene = test::one_body_scene(32, /*periodic=*/false, 0.25, 1.5, 1.0e3);
  scene.bodies.clear();
  scene.walls.top.speed = 1.0;
  Simulation sim(scene);
  BOOST_TEST(!lists_stage(sim, "immersed-boundary"));
  BOOST_TEST(!lists_stage(sim, "bodies"));
  run_steps(sim, 5, 0.005);
  BOOST_TEST(sim.timers().calls(Stage::predictor) == 5);
  BOOST_TEST(sim.timers().calls(Stage::projection) == 5);
  for (Stage s : {Stage::schedules, Stage::ib_forcing, Stage::bodies, Stage::contacts}) {
    BOOST_TEST(sim.timers().calls(s) == 0);
    BOOST_TEST(sim.timers().seconds(s) == 0.0);
  }
}

BOOST_AUTO_TEST_CASE(one_body_scene_does_no_pair_search) {
  Scene scene = with_contacts(test::one_body_scene(32, /*periodic=*/false, 0.25, 1.5, 1.0e3));
  scene.fluid.gravity = {0.0, -1.0};
  Simulation sim(scene);
  BOOST_TEST(sim.has_contacts());
  BOOST_TEST(lists_stage(sim, "contacts"));
  BOOST_TEST(!lists_stage(sim, "pair search"));
  run_steps(sim, 5, 0.005);
  BOOST_TEST(sim.timers().calls(Stage::contacts) >= 5);  // wall contacts are evaluated every sub-step
  BOOST_TEST(sim.stats().total_pair_checks == 0);
}

BOOST_AUTO_TEST_CASE(two_body_scene_searches_pairs) {
  Scene scene = with_contacts(test::one_body_scene(32, /*periodic=*/false, 0.2, 1.5, 1.0e3));
  scene.bodies[0].centre = {0.35, 0.5};
  scene.bodies.push_back(scene.bodies[0]);
  scene.bodies[1].centre = {0.65, 0.5};
  {  // global sub-steps: the pair search runs every sub-step
    scene.run.solid_substeps = RunSpec::SolidSubsteps::global;
    Simulation sim(scene);
    BOOST_TEST(lists_stage(sim, "pair search"));
    run_steps(sim, 5, 0.005);
    BOOST_TEST(sim.stats().total_pair_checks > 0);
  }
  {  // per group (default): bodies 0.1 apart cannot touch within a step, so each is a group of
     // one and no pair is searched
    scene.run.solid_substeps = RunSpec::SolidSubsteps::per_group;
    Simulation sim(scene);
    run_steps(sim, 5, 0.005);
    BOOST_TEST(sim.stats().total_pair_checks == 0);
  }
  {  // per group, bodies 0.004 apart: one group, searched
    scene.bodies[0].centre = {0.398, 0.5};
    scene.bodies[1].centre = {0.602, 0.5};
    Simulation sim(scene);
    run_steps(sim, 5, 0.005);
    BOOST_TEST(sim.stats().total_pair_checks > 0);
  }
}
