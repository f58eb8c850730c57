// A valid scene is read with defaults filled in; the resolved text reads back to the same
// scene; `--set` overrides reach keys absent from the file; mutated text never escapes as
// anything but InputError (the reader will be fuzzed).
#define BOOST_TEST_MODULE scene_reader
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>
#include <string>

#include "core/errors.hpp"
#include "scene/scene_reader.hpp"
#include "scene_fixture.hpp"

using ibms::test::good_scene_text;

BOOST_AUTO_TEST_CASE(good_scene_is_read_and_defaults_are_filled) {
  const ibms::Scene scene = ibms::read_scene_string(good_scene_text(), "good.toml");
  BOOST_TEST(scene.source_file == "good.toml");
  BOOST_TEST(scene.run.end_time == 2.5);
  BOOST_TEST(scene.run.cfl == 0.5);                      // default
  BOOST_TEST(std::isinf(scene.run.max_time_step));       // default: no cap
  BOOST_TEST(scene.domain.cells_x == 32);
  BOOST_TEST(!scene.domain.periodic_x);
  BOOST_TEST(scene.fluid.kinematic_viscosity == 0.012345678901234567);
  BOOST_TEST(scene.fluid.density == 1.0);                // default
  BOOST_TEST(scene.fluid.gravity[1] == -1.0);
  BOOST_TEST(scene.walls.top.speed == 1.0);
  BOOST_TEST(std::isinf(scene.walls.top.stop_time));     // default: never stops
  BOOST_TEST(scene.walls.bottom.speed == 0.0);
  BOOST_TEST(scene.ibm.kernel == "peskin4");
  BOOST_TEST(scene.ibm.forcing_passes == 1);             // default
  BOOST_TEST(scene.ibm.inner_fluid_inertia == "kempe");  // default
  BOOST_TEST_REQUIRE(scene.bodies.size() == 2u);
  BOOST_TEST(scene.bodies[0].centre[0] == 0.3);
  BOOST_TEST(scene.bodies[0].spring_damping < 0.0);      // default: from restitution
  BOOST_TEST(scene.bodies[0].restitution_coefficient == 1.0);
  BOOST_TEST(scene.bodies[0].mass_lumping == "equal");
  BOOST_TEST(!scene.bodies[0].swelling.enabled);
  BOOST_TEST(scene.bodies[1].spring_stiffness == 100.0);  // integer accepted for a float
  BOOST_TEST(scene.bodies[1].n_surface_points == 40);
  BOOST_TEST(scene.bodies[1].swelling.enabled);
  BOOST_TEST(scene.bodies[1].swelling.max_diameter == 0.3);
  BOOST_TEST(scene.contact.cds_radius_fraction == 0.1);
  BOOST_TEST(scene.contact.walls);                       // default
  BOOST_TEST(scene.output.file == ibms::test::output_path());
  BOOST_TEST(scene.output.series_every == 1);            // default
  BOOST_TEST(scene.resolved_text == ibms::resolved_scene_toml(scene));
}

BOOST_AUTO_TEST_CASE(resolved_scene_toml_reads_back_to_the_same_scene) {
  const std::string text = ibms::test::good_scene_with("[[bodies]]", "[[bodies]]\nspring_damping = 0.1");
  const ibms::Scene first = ibms::read_scene_string(text, "good.toml");
  BOOST_TEST_MESSAGE(first.resolved_text);
  const ibms::Scene again = ibms::read_scene_string(first.resolved_text, "good.toml");
  // The writer prints every field with round-trip precision, so equal text means equal values.
  BOOST_TEST(again.resolved_text == first.resolved_text);
  BOOST_TEST(again.fluid.kinematic_viscosity == first.fluid.kinematic_viscosity);
  BOOST_TEST(std::isinf(again.walls.left.stop_time));
  BOOST_TEST(again.bodies[0].spring_damping == 0.1);
  BOOST_TEST(again.bodies[1].spring_damping < 0.0);
  BOOST_TEST(again.bodies[1].swelling.enabled);
  BOOST_TEST(again.bodies[1].swelling.onset_time == 0.1);
  BOOST_TEST(!again.bodies[0].swelling.enabled);
}

BOOST_AUTO_TEST_CASE(overrides_set_keys_absent_from_the_file) {
  const std::string other_output = ibms::test::output_path() + ".other.h5";
  const ibms::Scene scene = ibms::read_scene_string(
      good_scene_text(), "good.toml",
      {"walls.left.stop_time=2", "run.cfl = 0.25", "bodies.0.swelling.rate=0.01",
       "bodies.0.swelling.max_diameter=0.25", "fluid.gravity=[0, -9.81]", "output.progress=false",
       "ibm.kernel=bkp6", "output.file=" + other_output, "bodies.1.diameter=0.22"});
  BOOST_TEST(scene.walls.left.stop_time == 2.0);
  BOOST_TEST(scene.run.cfl == 0.25);
  BOOST_TEST(scene.bodies[0].swelling.enabled);
  BOOST_TEST(scene.bodies[0].swelling.rate == 0.01);
  BOOST_TEST(scene.bodies[0].swelling.onset_time == 0.0);  // default
  BOOST_TEST(scene.fluid.gravity[1] == -9.81);
  BOOST_TEST(!scene.output.progress);
  BOOST_TEST(scene.ibm.kernel == "bkp6");                  // not TOML: taken as a string
  BOOST_TEST(scene.output.file == other_output);
  BOOST_TEST(scene.bodies[1].diameter == 0.22);
}

BOOST_AUTO_TEST_CASE(missing_scene_file_is_an_input_error_naming_the_path) {
  try {
    ibms::read_scene_file("/nonexistent_ibms_dir/scene.toml");
    BOOST_FAIL("no InputError thrown");
  } catch (const ibms::InputError& error) {
    BOOST_TEST(std::string(error.what()).find("/nonexistent_ibms_dir/scene.toml: ") == 0u, error.what());
  }
}

BOOST_AUTO_TEST_CASE(mutated_scenes_throw_nothing_but_input_error) {
  // Byte flips, deletions and duplications of the valid scene: a cheap stand-in for fuzzing.
  std::mt19937 random(/*seed=*/12345);
  const std::string base = good_scene_text();
  int n_rejected = 0;
  const int n_trials = 3000;
  for (int trial = 0; trial < n_trials; ++trial) {
    std::string text = base;
    const int n_edits = 1 + static_cast<int>(random() % 4);
    for (int edit = 0; edit < n_edits && !text.empty(); ++edit) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text[at] = static_cast<char>(random() % 256); break;
        case 1: text.erase(at, 1 + random() % 8); break;
        default: text.insert(at, text.substr(at, 1 + random() % 16)); break;
      }
    }
    try {
      ibms::read_scene_string(text, "mutant.toml");
    } catch (const ibms::InputError&) {
      ++n_rejected;
    }
  }
  BOOST_TEST_MESSAGE(n_rejected << " of " << n_trials << " mutated scenes rejected with InputError");
  BOOST_TEST(n_rejected > 0);
}
