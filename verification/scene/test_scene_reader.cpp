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
  BOOST_TEST((scene.ibm.kernel == ibms::IbmSpec::Kernel::peskin4));
  BOOST_TEST(scene.ibm.forcing_passes == 1);             // default
  BOOST_TEST((scene.ibm.inner_fluid_inertia == ibms::IbmSpec::InnerFluidInertia::kempe_by_mass));  // default
  BOOST_TEST_REQUIRE(scene.bodies.size() == 2u);
  BOOST_TEST(scene.bodies[0].centre[0] == 0.3);
  BOOST_TEST(scene.bodies[0].spring_damping < 0.0);      // default: from restitution
  BOOST_TEST(scene.bodies[0].restitution_coefficient == 1.0);
  BOOST_TEST((scene.bodies[0].mass_lumping == ibms::BodySpec::MassLumping::equal));
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

namespace {

// Every field of two scenes, compared as values (not through the writer's text).
void check_same_scene(const ibms::Scene& a, const ibms::Scene& b) {
  const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  BOOST_TEST(same(a.run.end_time, b.run.end_time));
  BOOST_TEST(same(a.run.time_step, b.run.time_step));
  BOOST_TEST(same(a.run.cfl, b.run.cfl));
  BOOST_TEST(same(a.run.max_time_step, b.run.max_time_step));
  BOOST_TEST(same(a.run.steady_tolerance, b.run.steady_tolerance));
  BOOST_TEST(a.run.max_steps == b.run.max_steps);
  BOOST_TEST(same(a.run.max_cfl, b.run.max_cfl));
  BOOST_TEST(same(a.run.max_viscous_number, b.run.max_viscous_number));
  BOOST_TEST((a.domain.cells_x == b.domain.cells_x && a.domain.cells_y == b.domain.cells_y));
  BOOST_TEST((same(a.domain.length_x, b.domain.length_x) && same(a.domain.length_y, b.domain.length_y)));
  BOOST_TEST((a.domain.periodic_x == b.domain.periodic_x && a.domain.periodic_y == b.domain.periodic_y));
  BOOST_TEST(same(a.fluid.density, b.fluid.density));
  BOOST_TEST(same(a.fluid.kinematic_viscosity, b.fluid.kinematic_viscosity));
  BOOST_TEST((a.fluid.gravity == b.fluid.gravity));
  for (const auto& [wa, wb] : {std::pair{a.walls.left, b.walls.left}, std::pair{a.walls.right, b.walls.right},
                               std::pair{a.walls.bottom, b.walls.bottom}, std::pair{a.walls.top, b.walls.top}})
    BOOST_TEST((same(wa.speed, wb.speed) && same(wa.stop_time, wb.stop_time) && wa.kind == wb.kind &&
                wa.profile == wb.profile && same(wa.velocity, wb.velocity) && wa.time_factor == wb.time_factor &&
                same(wa.ramp_time, wb.ramp_time) && same(wa.factor_offset, wb.factor_offset) &&
                same(wa.factor_amplitude, wb.factor_amplitude) && same(wa.factor_period, wb.factor_period)));
  BOOST_TEST((a.ibm.kernel == b.ibm.kernel && a.ibm.forcing_passes == b.ibm.forcing_passes));
  BOOST_TEST((a.ibm.forcing_stage == b.ibm.forcing_stage && a.ibm.inner_fluid_inertia == b.ibm.inner_fluid_inertia));
  BOOST_TEST(a.ibm.sub_markers == b.ibm.sub_markers);
  BOOST_TEST(a.ibm.marker_retraction == b.ibm.marker_retraction);
  BOOST_TEST(a.ibm.preconditioner_drift == b.ibm.preconditioner_drift);
  BOOST_TEST_REQUIRE(a.bodies.size() == b.bodies.size());
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    const ibms::BodySpec &x = a.bodies[k], &y = b.bodies[k];
    BOOST_TEST_CONTEXT("body " << k) {
      BOOST_TEST((x.kind == y.kind));
      BOOST_TEST((x.centre == y.centre && x.velocity == y.velocity && same(x.angular_velocity, y.angular_velocity)));
      BOOST_TEST((same(x.diameter, y.diameter) && x.n_surface_points == y.n_surface_points && same(x.density, y.density)));
      BOOST_TEST((x.oscillation_amplitude == y.oscillation_amplitude && same(x.angle_amplitude, y.angle_amplitude)));
      BOOST_TEST((same(x.oscillation_period, y.oscillation_period) && same(x.oscillation_phase, y.oscillation_phase)));
      BOOST_TEST((same(x.reference_speed, y.reference_speed) && same(x.reference_length, y.reference_length)));
      BOOST_TEST((same(x.spring_stiffness, y.spring_stiffness) && same(x.spring_damping, y.spring_damping)));
      BOOST_TEST((same(x.restitution_coefficient, y.restitution_coefficient) && x.cross_springs == y.cross_springs));
      BOOST_TEST((x.mass_lumping == y.mass_lumping));
      BOOST_TEST((x.swelling.enabled == y.swelling.enabled && same(x.swelling.onset_time, y.swelling.onset_time)));
      BOOST_TEST((same(x.swelling.rate, y.swelling.rate) && same(x.swelling.max_diameter, y.swelling.max_diameter)));
    }
  }
  BOOST_TEST((same(a.contact.stiffness, b.contact.stiffness) && same(a.contact.restitution_coefficient,
                                                                      b.contact.restitution_coefficient)));
  BOOST_TEST((same(a.contact.cds_radius, b.contact.cds_radius) && same(a.contact.cds_radius_fraction,
                                                                        b.contact.cds_radius_fraction)));
  BOOST_TEST(a.contact.walls == b.contact.walls);
  BOOST_TEST((a.contact.time_stepping == b.contact.time_stepping && a.contact.inner_step == b.contact.inner_step));
  BOOST_TEST(same(a.contact.outer_step_fraction, b.contact.outer_step_fraction));
  BOOST_TEST((a.output.file == b.output.file && a.output.series_every == b.output.series_every));
  BOOST_TEST((same(a.output.snapshot_interval, b.output.snapshot_interval) &&
              a.output.centreline_profiles == b.output.centreline_profiles));
  BOOST_TEST((a.output.progress == b.output.progress && a.output.checkpoint_every == b.output.checkpoint_every));
  BOOST_TEST((a.output.probes == b.output.probes));
}

}  // namespace

// The resolved text of a scene with every body kind and non-default values reads back to equal
// values field by field (not only to the same text, which would compare the writer with itself).
BOOST_AUTO_TEST_CASE(resolved_scene_of_every_body_kind_reads_back_to_equal_values) {
  std::string text = ibms::test::good_scene_with("[[bodies]]", "[[bodies]]\nspring_damping = 0.1\nangular_velocity = 0.25");
  text = ibms::test::replaced(text, "[contact]",
                                        "[[bodies]]\nkind = \"rigid\"\ncentre = [0.5, 0.8]\ndiameter = 0.1\n"
                                        "n_surface_points = 12\ndensity = 2.5\nvelocity = [0.1, -0.3]\n"
                                        "reference_speed = 0.7\n"
                                        "[[bodies]]\nkind = \"prescribed\"\ncentre = [0.5, 0.2]\ndiameter = 0.1\n"
                                        "n_surface_points = 12\noscillation_amplitude = [0.01, 0.02]\n"
                                        "angle_amplitude = 0.3\noscillation_period = 0.7\noscillation_phase = 1.1\n"
                                        "reference_length = 0.2\n[contact]");
  text = ibms::test::replaced(text, "[ibm]", "[ibm]\nforcing_stage = \"implicit_prediction\"\nforcing_passes = 3");
  const ibms::Scene first = ibms::read_scene_string(text, "good.toml");
  BOOST_TEST_REQUIRE(first.bodies.size() == 4u);
  BOOST_TEST((first.bodies[2].kind == ibms::BodySpec::Kind::rigid));
  BOOST_TEST(first.bodies[3].oscillation_phase == 1.1);
  const ibms::Scene again = ibms::read_scene_string(first.resolved_text, "good.toml");
  check_same_scene(first, again);
}

// ibm.preconditioner_drift is "auto" (the default) or a number of cells in [0, 1]; both read back
// from the resolved scene.
BOOST_AUTO_TEST_CASE(preconditioner_drift_is_auto_or_a_number_and_reads_back) {
  const ibms::Scene by_default = ibms::read_scene_string(good_scene_text(), "good.toml");
  BOOST_TEST(by_default.ibm.preconditioner_drift == ibms::IbmSpec::preconditioner_drift_auto);
  for (const std::string value : {"\"auto\"", "0", "0.1", "1"}) {
    const ibms::Scene scene = ibms::read_scene_string(good_scene_text(), "good.toml", {"ibm.preconditioner_drift=" + value});
    BOOST_TEST(scene.ibm.preconditioner_drift ==
               (value == "\"auto\"" ? ibms::IbmSpec::preconditioner_drift_auto : std::stod(value)));
    check_same_scene(scene, ibms::read_scene_string(scene.resolved_text, "good.toml"));
  }
}

// contact.outer_step_fraction is 1/16 by default (inner_loop_outer_fraction) or a number in (0, 1];
// it reads back from the resolved scene.
BOOST_AUTO_TEST_CASE(outer_step_fraction_defaults_to_a_sixteenth_and_reads_back) {
  const ibms::Scene by_default = ibms::read_scene_string(good_scene_text(), "good.toml");
  BOOST_TEST(by_default.contact.outer_step_fraction == 0.0625);
  for (const double value : {0.5, 1.0}) {
    const ibms::Scene scene =
        ibms::read_scene_string(good_scene_text(), "good.toml", {"contact.outer_step_fraction=" + std::to_string(value)});
    BOOST_TEST(scene.contact.outer_step_fraction == value);
    check_same_scene(scene, ibms::read_scene_string(scene.resolved_text, "good.toml"));
  }
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
  BOOST_TEST((scene.ibm.kernel == ibms::IbmSpec::Kernel::bkp6));  // not TOML: taken as a string
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

// Open sides: every side kind with its keys, the inflow's time factors, and the probes
// read back from the resolved text to equal values; the sides are as written.
BOOST_AUTO_TEST_CASE(open_sides_and_probes_read_back_to_equal_values) {
  for (const char* factor : {"time_factor = \"sinusoidal\"\nfactor_offset = 1.0\nfactor_amplitude = 0.25\nfactor_period = 0.3",
                             "time_factor = \"ramp\"\nramp_time = 0.7"}) {
    const std::string text = std::string(R"([run]
end_time = 1.0
[domain]
length_x = 2.2
length_y = 0.41
cells_x = 44
cells_y = 8
[fluid]
kinematic_viscosity = 0.001
[walls.left]
kind = "inflow"
profile = "parabolic"
velocity = 1.5
)") + factor + R"(
[walls.right]
kind = "outflow"
[walls.bottom]
speed = 0.125
stop_time = 0.5
[output]
file = ")" + ibms::test::output_path() + R"("
probes = [[0.14, 0.2], [0.26, 0.2]]
)";
    const ibms::Scene first = ibms::read_scene_string(text, "channel.toml");
    const ibms::Scene again = ibms::read_scene_string(first.resolved_text, "channel.toml");
    check_same_scene(first, again);
    BOOST_TEST((first.walls.left.kind == ibms::WallSpec::Kind::inflow));
    BOOST_TEST((first.walls.left.profile == ibms::WallSpec::Profile::parabolic));
    BOOST_TEST((first.walls.right.kind == ibms::WallSpec::Kind::outflow));
    BOOST_TEST((first.walls.bottom.kind == ibms::WallSpec::Kind::wall));
    BOOST_TEST(first.walls.bottom.speed == 0.125);
    BOOST_TEST(first.output.probes.size() == 2u);
    BOOST_TEST(first.output.probes[1][0] == 0.26);
  }
}
