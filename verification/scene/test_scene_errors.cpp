// Bad scenes are rejected with ONE line naming the file, the key and the reason (docs/design.md §4).
// A data-driven table: each row is a valid scene (scene_fixture.hpp) spoiled in one way.
#define BOOST_TEST_MODULE scene_errors
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "scene/scene_reader.hpp"
#include "scene_fixture.hpp"

namespace {

using ibms::test::good_scene_text;
using ibms::test::good_scene_with;

struct BadScene {
  std::string what;                    // the fault, for the log
  std::string text;                    // TOML text
  std::vector<std::string> overrides;  // --set texts
  std::string key;                     // the message must name this key (or "--set ..." text)
};

const std::string source_name = "bad_scene.toml";

std::vector<BadScene> bad_scenes() {
  const std::string body0 = "centre = [0.3, 0.5]\ndiameter = 0.2\n";
  const std::string body1 = "centre = [0.7, 0.5]\ndiameter = 0.2\n";
  return {
      {"malformed TOML (unclosed header)", good_scene_with("[domain]", "[domain"), {}, "TOML syntax"},
      {"malformed TOML (duplicate key)", good_scene_with("end_time = 2.5", "end_time = 2.5\nend_time = 3"), {}, "TOML syntax"},
      {"malformed TOML (bad value)", good_scene_with("cells_y = 32", "cells_y = 3 2"), {}, "TOML syntax"},
      {"empty scene", "", {}, "run.end_time"},
      {"unknown body kind", good_scene_with(body0, "kind = \"elastic\"\n" + body0), {}, "bodies.0.kind"},
      {"density on a prescribed body", good_scene_with(body0, "kind = \"prescribed\"\n" + body0), {}, "bodies.0.density"},
      {"spring_stiffness on a rigid body",
       good_scene_with(body0 + "n_surface_points = 32\ndensity = 1.5\n", "kind = \"rigid\"\n" + body0 + "n_surface_points = 32\ndensity = 1.5\n"),
       {}, "bodies.0.spring_stiffness"},
      {"swelling on a rigid body (--set kind)", good_scene_text(), {"bodies.1.kind=\"rigid\""}, "bodies.1.spring_stiffness"},
      {"oscillation without a period",
       good_scene_with(body0 + "n_surface_points = 32\ndensity = 1.5\nspring_stiffness = 100.0\n",
                       "kind = \"prescribed\"\n" + body0 + "n_surface_points = 32\noscillation_amplitude = [0.01, 0.0]\n"),
       {}, "bodies.0.oscillation_period"},
      {"negative reference speed", good_scene_text(), {"bodies.0.reference_speed=-1"}, "bodies.0.reference_speed"},
      {"unknown forcing stage", good_scene_with("[ibm]", "[ibm]\nforcing_stage = \"late\""), {}, "ibm.forcing_stage"},
      {"preconditioner drift neither auto nor a number", good_scene_text(), {"ibm.preconditioner_drift=\"often\""},
       "ibm.preconditioner_drift"},
      {"preconditioner drift negative", good_scene_text(), {"ibm.preconditioner_drift=-0.1"}, "ibm.preconditioner_drift"},
      {"preconditioner drift a boolean", good_scene_text(), {"ibm.preconditioner_drift=true"}, "ibm.preconditioner_drift"},
      {"unknown key (misspelt)", good_scene_with("kinematic_viscosity", "kinematic_viscosty"), {}, "fluid.kinematic_viscosty"},
      {"unknown section", good_scene_with("[ibm]", "[solver]\n[ibm]"), {}, "solver"},
      {"unsupported [[body_groups]]", good_scene_text() + "[[body_groups]]\ncount = 3\n", {}, "body_groups"},
      {"key above its section header", "end_time = 1.0\n" + good_scene_text(), {}, "end_time"},
      {"section is not a table", "ibm = 3\n" + good_scene_with("[ibm]\n", ""), {}, "ibm"},
      {"unknown wall", good_scene_with("[walls.top]", "[walls.front]"), {}, "walls.front"},
      {"unknown key in a wall", good_scene_with("speed = 1.0", "velocity = 1.0"), {}, "walls.top.velocity"},
      {"wrong type: string for integer", good_scene_with("cells_x = 32", "cells_x = \"32\""), {}, "domain.cells_x"},
      {"wrong type: float for integer", good_scene_with("cells_x = 32", "cells_x = 32.0"), {}, "domain.cells_x"},
      {"wrong type: integer for boolean", good_scene_with("[domain]", "[domain]\nperiodic_x = 1"), {}, "domain.periodic_x"},
      {"wrong type: gravity with one component", good_scene_with("[0.0, -1.0]", "[-1.0]"), {}, "fluid.gravity"},
      {"missing kinematic_viscosity", good_scene_with("kinematic_viscosity = 0.012345678901234567\n", ""), {}, "fluid.kinematic_viscosity"},
      {"missing end_time", good_scene_with("end_time = 2.5\n", ""), {}, "run.end_time"},
      {"missing [domain]", good_scene_with("[domain]\nlength_x = 1.0\nlength_y = 1.0\ncells_x = 32\ncells_y = 32\n", ""), {}, "domain.length_x"},
      {"missing body density", good_scene_with(body0 + "n_surface_points = 32\ndensity = 1.5\n", body0 + "n_surface_points = 32\n"), {}, "bodies.0.density"},
      {"zero viscosity", good_scene_with("kinematic_viscosity = 0.012345678901234567", "kinematic_viscosity = 0"), {}, "fluid.kinematic_viscosity"},
      {"negative viscosity", good_scene_with("kinematic_viscosity = 0.012345678901234567", "kinematic_viscosity = -0.01"), {}, "fluid.kinematic_viscosity"},
      {"nan viscosity", good_scene_with("kinematic_viscosity = 0.012345678901234567", "kinematic_viscosity = nan"), {}, "fluid.kinematic_viscosity"},
      {"zero fluid density", good_scene_with("[fluid]", "[fluid]\ndensity = 0.0"), {}, "fluid.density"},
      {"negative body density", good_scene_with(body1 + "n_surface_points = 40\ndensity = 1.5", body1 + "n_surface_points = 40\ndensity = -1.5"), {}, "bodies.1.density"},
      {"too few cells", good_scene_with("cells_x = 32", "cells_x = 2"), {}, "domain.cells_x"},
      {"cell count beyond int", good_scene_with("cells_y = 32", "cells_y = 9999999999"), {}, "domain.cells_y"},
      {"zero length", good_scene_with("length_y = 1.0", "length_y = 0.0"), {}, "domain.length_y"},
      {"negative time step", good_scene_with("end_time = 2.5", "end_time = 2.5\ntime_step = -0.001"), {}, "run.time_step"},
      {"negative end time", good_scene_with("end_time = 2.5", "end_time = -1.0"), {}, "run.end_time"},
      {"cfl above 2", good_scene_with("end_time = 2.5", "end_time = 2.5\ncfl = 3"), {}, "run.cfl"},
      {"adaptive cfl at run.max_cfl", good_scene_with("end_time = 2.5", "end_time = 2.5\ncfl = 1.0"), {}, "run.cfl"},
      {"run.max_cfl below the adaptive cfl (--set)", good_scene_text(), {"run.max_cfl=0.4"}, "run.max_cfl"},
      {"zero max_time_step", good_scene_with("end_time = 2.5", "end_time = 2.5\nmax_time_step = 0"), {}, "run.max_time_step"},
      {"body outside the box", good_scene_with("centre = [0.3, 0.5]", "centre = [1.5, 0.5]"), {}, "bodies.0.centre"},
      {"body overlapping a wall", good_scene_with("centre = [0.3, 0.5]", "centre = [0.05, 0.5]"), {}, "bodies.0.centre"},
      {"body overlapping another", good_scene_with("centre = [0.7, 0.5]", "centre = [0.45, 0.5]"), {}, "bodies.1.centre"},
      {"n_surface_points below 3", good_scene_with("n_surface_points = 32", "n_surface_points = 2"), {}, "bodies.0.n_surface_points"},
      {"body restitution 0", good_scene_with(body0, body0 + "restitution_coefficient = 0.0\n"), {}, "bodies.0.restitution_coefficient"},
      {"body restitution 1.5", good_scene_with(body0, body0 + "restitution_coefficient = 1.5\n"), {}, "bodies.0.restitution_coefficient"},
      {"negative spring damping", good_scene_with(body0, body0 + "spring_damping = -1.0\n"), {}, "bodies.0.spring_damping"},
      {"unknown mass lumping", good_scene_with(body0, body0 + "mass_lumping = \"lumped\"\n"), {}, "bodies.0.mass_lumping"},
      {"swelling max below diameter", good_scene_with("max_diameter = 0.3", "max_diameter = 0.15"), {}, "bodies.1.swelling.max_diameter"},
      {"swelling without rate", good_scene_with("rate = 0.05, ", ""), {}, "bodies.1.swelling.rate"},
      {"unknown kernel", good_scene_with("\"peskin4\"", "\"peskin5\""), {}, "ibm.kernel"},
      {"unknown inner fluid inertia", good_scene_with("[ibm]", "[ibm]\ninner_fluid_inertia = \"full\""), {}, "ibm.inner_fluid_inertia"},
      {"zero forcing passes", good_scene_with("[ibm]", "[ibm]\nforcing_passes = 0"), {}, "ibm.forcing_passes"},
      {"inflow without an outflow", good_scene_text(), {"walls.left.kind=\"inflow\"", "walls.left.velocity=1"}, "walls.left.kind"},
      {"inflow without its velocity", good_scene_text(), {"walls.left.kind=\"inflow\"", "walls.right.kind=\"outflow\""}, "walls.left.velocity"},
      {"periodic opposite a wall", good_scene_text(), {"walls.left.kind=\"periodic\""}, "walls.left.kind"},
      {"wall on a periodic direction", good_scene_with("cells_x = 32", "cells_x = 32\nperiodic_x = true"), {"walls.right.kind=\"wall\""}, "walls.right.kind"},
      {"two outflows without an inflow", good_scene_text(), {"walls.left.kind=\"outflow\"", "walls.right.kind=\"outflow\""}, "walls.left.kind"},
      {"wall speed on an outflow", good_scene_with("[walls.top]\nspeed = 1.0", "[walls.top]\nkind = \"outflow\"\nspeed = 1.0"), {"walls.bottom.kind=\"inflow\"", "walls.bottom.velocity=1"}, "walls.top.speed"},
      {"ramp without its time", good_scene_text(), {"walls.left.kind=\"inflow\"", "walls.left.velocity=1", "walls.left.time_factor=\"ramp\"", "walls.right.kind=\"outflow\""}, "walls.left.ramp_time"},
      {"unknown inflow profile", good_scene_text(), {"walls.left.kind=\"inflow\"", "walls.left.velocity=1", "walls.left.profile=\"cubic\"", "walls.right.kind=\"outflow\""}, "walls.left.profile"},
      {"body within the kernel's reach of an outflow", good_scene_text(), {"walls.left.kind=\"inflow\"", "walls.left.velocity=1", "walls.right.kind=\"outflow\"", "bodies.1.centre=[0.85, 0.5]"}, "bodies.1.centre"},
      {"wall speed on a periodic side", good_scene_with("cells_y = 32", "cells_y = 32\nperiodic_y = true"), {}, "walls.top.speed"},
      {"contact stiffness without radius", good_scene_with("cds_radius_fraction = 0.1", "cds_radius_fraction = 0.0"), {}, "contact.stiffness"},
      {"contact restitution 0", good_scene_with("[contact]", "[contact]\nrestitution_coefficient = 0"), {}, "contact.restitution_coefficient"},
      {"unknown contact model", good_scene_text(), {"contact.model=\"hertz\""}, "contact.model"},
      {"collision_time with a stiffness", good_scene_text(), {"contact.model=\"collision_time\""}, "contact.stiffness"},
      {"collision_time without radius", good_scene_text(),
       {"contact.model=\"collision_time\"", "contact.stiffness=0", "contact.cds_radius_fraction=0"}, "contact.model"},
      {"collision lasting under a fluid step", good_scene_text(),
       {"contact.model=\"collision_time\"", "contact.stiffness=0", "contact.collision_steps=0.5"}, "contact.collision_steps"},
      {"collision_steps zero", good_scene_text(),
       {"contact.model=\"collision_time\"", "contact.stiffness=0", "contact.collision_steps=0"}, "contact.collision_steps"},
      {"collision_steps not finite", good_scene_text(),
       {"contact.model=\"collision_time\"", "contact.stiffness=0", "contact.collision_steps=inf"}, "contact.collision_steps"},
      {"zero series_every", good_scene_with("[output]", "[output]\nseries_every = 0"), {}, "output.series_every"},
      {"unwritable output directory", good_scene_with(ibms::test::output_path(), "/nonexistent_ibms_dir/out.h5"), {}, "output.file"},
      {"zero cell count", good_scene_with("cells_x = 32", "cells_x = 0"), {}, "domain.cells_x"},
      {"negative cell count", good_scene_with("cells_y = 32", "cells_y = -32"), {}, "domain.cells_y"},
      {"zero body density", good_scene_with(body0 + "n_surface_points = 32\ndensity = 1.5", body0 + "n_surface_points = 32\ndensity = 0"), {}, "bodies.0.density"},
      {"zero end time", good_scene_with("end_time = 2.5", "end_time = 0.0"), {}, "run.end_time"},
      {"contact restitution 1.5", good_scene_with("[contact]", "[contact]\nrestitution_coefficient = 1.5"), {}, "contact.restitution_coefficient"},
      {"outer step fraction 0", good_scene_text(), {"contact.outer_step_fraction=0"}, "contact.outer_step_fraction"},
      {"outer step fraction 2", good_scene_text(), {"contact.outer_step_fraction=2"}, "contact.outer_step_fraction"},
      {"outer step fraction text", good_scene_text(), {"contact.outer_step_fraction=\"half\""}, "contact.outer_step_fraction"},
      {"negative body restitution", good_scene_with(body0, body0 + "restitution_coefficient = -0.5\n"), {}, "bodies.0.restitution_coefficient"},
      {"wrong type: string for real", good_scene_with("kinematic_viscosity = 0.012345678901234567", "kinematic_viscosity = \"small\""), {}, "fluid.kinematic_viscosity"},
      {"wrong type: table for body centre", good_scene_with("centre = [0.3, 0.5]", "centre = { x = 0.3, y = 0.5 }"), {}, "bodies.0.centre"},
      {"missing body centre", good_scene_with("centre = [0.3, 0.5]\n", ""), {}, "bodies.0.centre"},
      {"output path is a directory", good_scene_with(ibms::test::output_path(), "/tmp"), {}, "output.file"},
      {"bad override key", good_scene_text(), {"fluid.viscosty=0.1"}, "--set fluid.viscosty=0.1"},
      {"override of an unknown section", good_scene_text(), {"solver.tolerance=1e-6"}, "--set solver.tolerance=1e-6"},
      {"override without '='", good_scene_text(), {"fluid.kinematic_viscosity"}, "--set fluid.kinematic_viscosity"},
      {"override of a missing body", good_scene_text(), {"bodies.5.diameter=0.1"}, "--set bodies.5.diameter=0.1"},
      {"override with wrong type", good_scene_text(), {"domain.cells_x=abc"}, "domain.cells_x"},
      {"override out of range", good_scene_text(), {"fluid.kinematic_viscosity=-1"}, "fluid.kinematic_viscosity"},
  };
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_bad_scene_throws_one_line_naming_file_key_and_reason) {
  const std::vector<BadScene> cases = bad_scenes();
  BOOST_TEST(cases.size() >= 30u);
  for (const BadScene& bad : cases) {
    BOOST_TEST_CONTEXT("case: " << bad.what) {
      std::string message;
      try {
        ibms::read_scene_string(bad.text, source_name, bad.overrides);
      } catch (const ibms::InputError& error) {
        message = error.what();
      }
      BOOST_TEST_MESSAGE(bad.what << "\n    -> " << message);
      BOOST_TEST(!message.empty(), "no InputError thrown");
      BOOST_TEST(message.find(source_name) == 0u, "message does not start with the file name");
      const auto key_at = message.find(bad.key);
      BOOST_TEST(key_at != std::string::npos, "message does not name " << bad.key);
      // A reason follows the key: "...<key>: <reason>" or "...<key> (--set ...): <reason>".
      const auto reason_at = message.find(": ", key_at == std::string::npos ? 0 : key_at);
      BOOST_TEST((reason_at != std::string::npos && message.size() > reason_at + 4), "no reason");
      BOOST_TEST(message.find('\n') == std::string::npos, "message is not one line");
    }
  }
}

BOOST_AUTO_TEST_CASE(error_points_at_line_and_column_of_the_bad_value) {
  // kinematic_viscosity is on line 10 of the fixture; the value starts at column 23.
  const std::string text = good_scene_with("kinematic_viscosity = 0.012345678901234567",
                                           "kinematic_viscosity = -2.0");
  try {
    ibms::read_scene_string(text, source_name);
    BOOST_FAIL("no InputError thrown");
  } catch (const ibms::InputError& error) {
    BOOST_TEST(std::string(error.what()).find("bad_scene.toml:10:23: fluid.kinematic_viscosity: ") == 0u,
               error.what());
  }
}

BOOST_AUTO_TEST_CASE(adaptive_cfl_not_below_max_cfl_names_both_keys_and_a_fixed_step_is_accepted) {
  // With the adaptive step, run.cfl >= run.max_cfl would let the guard stop a sound run.
  std::string message;
  try {
    ibms::read_scene_string(good_scene_with("end_time = 2.5", "end_time = 2.5\ncfl = 1.2\nmax_cfl = 1.0"), source_name);
  } catch (const ibms::InputError& error) {
    message = error.what();
  }
  BOOST_TEST_MESSAGE(message);
  BOOST_TEST(message.find("bad_scene.toml:") == 0u);
  BOOST_TEST(message.find("run.cfl") != std::string::npos);
  BOOST_TEST(message.find("run.max_cfl") != std::string::npos);
  // run.cfl plays no part with a fixed run.time_step, and below run.max_cfl it is fine.
  BOOST_CHECK_NO_THROW(ibms::read_scene_string(
      good_scene_with("end_time = 2.5", "end_time = 2.5\ntime_step = 0.001\ncfl = 1.2\nmax_cfl = 1.0"), source_name));
  BOOST_CHECK_NO_THROW(ibms::read_scene_string(
      good_scene_with("end_time = 2.5", "end_time = 2.5\ncfl = 0.9\nmax_cfl = 1.0"), source_name));
}
