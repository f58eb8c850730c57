// Restart: a run stopped at step M and continued with --restart from its
// /checkpoint ends bit-identical to the run that never stopped, with bodies, swelling and DEM
// contacts active; the checkpoint's format version, scene and sizes are checked by the reader.
#define BOOST_TEST_MODULE restart
#include <boost/test/unit_test.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <utility>
#include <string>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/output_file.hpp"
#include "scene/scene_reader.hpp"
#include "sim/run/run.hpp"
#include "fluid/spectral_solver.hpp"
#include "fluid/threads.hpp"
#include "sim/run/simulation_checkpoint.hpp"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() : path(fs::temp_directory_path() / ("ibms_restart_" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

// verification/sim/restart_scene.toml with its output in `output` and further overrides.
ibms::Scene scene_for(const std::string& output, std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), "output.file=" + output);
  return ibms::read_scene_file(IBMS_RESTART_SCENE, overrides);
}

ibms::RunSummary run(const ibms::Scene& scene, const std::string& restart = "") {
  ibms::Simulation sim(scene);
  return ibms::run_simulation(sim, {scene.output.file, /*quiet=*/true, restart, nullptr});
}

// Bitwise equality of two doubles (NaN payloads and signed zeros included).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The finite values of /series/<name> in an output file; "body_NNN/<quantity>" is column NNN of
// /series/per_body/<quantity>.
std::vector<double> series(const std::string& file, const std::string& name) {
  std::string path = "/series/" + name;
  std::size_t column = 0;
  const bool per_body = name.rfind("body_", 0) == 0;
  if (per_body) {
    column = std::stoul(name.substr(5, 3));
    path = "/series/per_body/" + name.substr(name.find('/') + 1);
  }
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  const hid_t s = H5Dget_space(d);
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(s, dims, nullptr);
  std::vector<double> table(dims[0] * (per_body ? dims[1] : 1));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, table.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  std::vector<double> values(dims[0]);
  for (hsize_t k = 0; k < dims[0]; ++k) values[k] = per_body ? table[k * dims[1] + column] : table[k];
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  return values;
}

// The rows of /series/<name> of `rest` (a restarted run) and the rows of the same steps of `whole`
// differ in no bit: the series carry no state that the checkpoint does not restore.
std::size_t n_different_series_values(const std::string& whole, const std::string& rest, const std::string& name) {
  const std::vector<double> step_whole = series(whole, "step"), step_rest = series(rest, "step");
  const std::vector<double> values_whole = series(whole, name), values_rest = series(rest, name);
  BOOST_REQUIRE(values_whole.size() == step_whole.size());
  BOOST_REQUIRE(values_rest.size() == step_rest.size());
  BOOST_REQUIRE(!step_rest.empty());
  std::size_t n_different = 0;
  for (std::size_t k = 0; k < step_rest.size(); ++k) {
    const auto at = std::find(step_whole.begin(), step_whole.end(), step_rest[k]);
    BOOST_REQUIRE(at != step_whole.end());
    n_different += same_bits(values_rest[k], values_whole[static_cast<std::size_t>(at - step_whole.begin())]) ? 0 : 1;
  }
  return n_different;
}

// Largest value of /series/<name> (to show a mechanism was active); -inf if none.
double series_max(const std::string& file, const std::string& name) {
  const std::vector<double> values = series(file, name);
  return values.empty() ? -HUGE_VAL : *std::max_element(values.begin(), values.end());
}

}  // namespace

// Number of values (arrays and scalars) of the two files' checkpoints that differ in any bit.
std::size_t n_different_values(const std::string& file_a, const std::string& file_b) {
  const ibms::Checkpoint a = ibms::read_checkpoint(file_a);
  const ibms::Checkpoint b = ibms::read_checkpoint(file_b);
  BOOST_REQUIRE(a.arrays.size() == b.arrays.size());
  BOOST_REQUIRE(a.scalars.size() == b.scalars.size());
  std::size_t n_values = 0, n_different = 0;
  for (const auto& [name, values] : a.arrays) {
    const std::vector<double>& other = b.arrays.at(name);
    BOOST_REQUIRE_MESSAGE(values.size() == other.size(), name);
    for (std::size_t k = 0; k < values.size(); ++k) n_different += same_bits(values[k], other[k]) ? 0 : 1;
    n_values += values.size();
  }
  for (const auto& [name, value] : a.scalars) {
    n_different += same_bits(value, b.scalars.at(name)) ? 0 : 1;
    n_values += 1;
  }
  BOOST_TEST_MESSAGE("compared " << n_values << " state values bit by bit: " << n_different << " differ");
  return n_different;
}

BOOST_AUTO_TEST_CASE(restarted_run_ends_bit_identical_with_bodies_swelling_and_contacts) {
  const TempDir dir;
  const ibms::RunSummary whole = run(scene_for(dir.file("whole.h5")));
  const ibms::RunSummary first = run(scene_for(dir.file("first.h5"), {"run.max_steps=137"}));
  BOOST_TEST(first.steps == 137);
  const ibms::RunSummary rest = run(scene_for(dir.file("rest.h5")), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  BOOST_TEST(whole.steps == 300);

  // The mechanisms the claim is about were active in the second half (after the restart).
  BOOST_TEST(series_max(dir.file("rest.h5"), "contact/n_wall_contacts") > 0.0);
  BOOST_TEST(series_max(dir.file("rest.h5"), "contact/n_active_pairs") > 0.0);
  BOOST_TEST(series_max(dir.file("rest.h5"), "body_001/diameter") > 0.2 + 0.05 * 0.6);

  // 7 fluid arrays, the FFTW wisdom, 8 per-body arrays and their counts, however many bodies.
  BOOST_TEST(ibms::read_checkpoint(dir.file("whole.h5")).arrays.size() == 7u + 1u + 2u * 8u);
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
}

BOOST_AUTO_TEST_CASE(restarted_run_with_the_no_slip_coupling_ends_bit_identical) {
  // The previous step's marker forces (the predictor of the no_slip coupling) are in the checkpoint.
  const TempDir dir;
  const std::vector<std::string> no_slip{"ibm.coupling=\"no_slip\"", "ibm.slip_tolerance=1e-4"};
  auto with = [&](std::vector<std::string> more) {
    more.insert(more.end(), no_slip.begin(), no_slip.end());
    return more;
  };
  const auto scene = [&](const std::string& name, std::vector<std::string> overrides) {
    overrides.push_back("output.file=\"" + dir.file(name) + "\"");
    return ibms::read_scene_file(IBMS_RESTART_SCENE_RIGID, with(overrides));
  };
  const ibms::RunSummary whole = run(scene("whole.h5", {}));
  run(scene("first.h5", {"run.max_steps=91"}));
  const ibms::RunSummary rest = run(scene("rest.h5", {}), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  BOOST_TEST(series_max(dir.file("rest.h5"), "coupling_iterations") > 0.0);  // corrections after the restart
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
}

// A moving body's own preconditioner block is kept while its markers drift less than
// ibm.preconditioner_drift cells; the checkpoint carries what the block in use was built from, so
// a run restarted while a block built steps earlier is in use builds that same block.
BOOST_AUTO_TEST_CASE(restarted_run_with_kept_preconditioner_blocks_ends_bit_identical) {
  const TempDir dir;
  const auto scene = [&](const std::string& name, std::vector<std::string> overrides) {
    for (const char* o : {"ibm.coupling=\"no_slip\"", "ibm.constrained_velocity=\"faces\"", "ibm.slip_tolerance=1e-4",
                          "ibm.preconditioner_drift=0.5"})
      overrides.push_back(o);
    overrides.push_back("output.file=\"" + dir.file(name) + "\"");
    return ibms::read_scene_file(IBMS_RESTART_SCENE_RIGID, overrides);
  };
  const ibms::RunSummary whole = run(scene("whole.h5", {}));
  run(scene("first.h5", {"run.max_steps=91"}));
  const ibms::RunSummary rest = run(scene("rest.h5", {}), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  BOOST_TEST(series_max(dir.file("rest.h5"), "coupling_iterations") > 0.0);  // corrections after the restart
  // At the restart both bodies' blocks were built at markers other than their rims' (no
  // retraction: the markers are the rim points; the rims have moved on by the last step since the
  // blocks were last compared with them): kept blocks, which the restart had to rebuild.
  const ibms::Checkpoint first = ibms::read_checkpoint(dir.file("first.h5"));
  const std::string path = dir.file("first.h5");
  const ibms::CheckpointReader read(first, path);
  const double h = 1.0 / 32;
  for (std::size_t b = 0; b < 2; ++b) {
    const ibms::BodySlice built = read.body_array("bodies_block_markers", b, 2);
    const ibms::BodySlice rim = read.body_array("bodies_position", b, 2);
    BOOST_REQUIRE(built.size == 32u);
    double drift = 0.0;
    for (std::size_t k = 0; k < built.size; ++k) drift = std::max(drift, std::abs(built.data[k] - rim.data[k]) / h);
    BOOST_TEST_MESSAGE("body " << b << ": block built " << drift << " cells from the rim at the restart");
    BOOST_TEST(drift > 0.0);
  }
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
}

BOOST_AUTO_TEST_CASE(restarted_run_with_mass_spring_bodies_under_the_no_slip_coupling_ends_bit_identical) {
  // The rim's response is rebuilt from the state at every step; the forces are the predictor. With
  // sub-markers (16 rim points 1.26 h apart: two markers an edge, more as one wheel swells) the
  // marker count changes from step to step and with it the predictor's use and the rims' block.
  for (const char* sub_markers : {"false", "true"}) {
    BOOST_TEST_CONTEXT("ibm.sub_markers = " << sub_markers) {
      const TempDir dir;
      const std::vector<std::string> on_faces{"ibm.coupling=\"no_slip\"", "ibm.constrained_velocity=\"faces\"",
                                              "ibm.rim_preconditioner=\"response\"",
                                              std::string("ibm.sub_markers=") + sub_markers};
      const auto scene = [&](const std::string& name, std::vector<std::string> overrides) {
        overrides.insert(overrides.end(), on_faces.begin(), on_faces.end());
        overrides.push_back("output.file=\"" + dir.file(name) + "\"");
        return ibms::read_scene_file(IBMS_RESTART_SCENE, overrides);
      };
      const ibms::RunSummary whole = run(scene("whole.h5", {}));
      run(scene("first.h5", {"run.max_steps=137"}));
      const ibms::RunSummary rest = run(scene("rest.h5", {}), dir.file("first.h5"));
      BOOST_TEST(rest.steps == whole.steps);
      BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
    }
  }
}

// At a fixed thread count of 2 (threaded loops and FFTs, body groups on two
// threads) the restart is bit-identical as well.
BOOST_AUTO_TEST_CASE(restarted_run_at_two_threads_ends_bit_identical) {
  ibms::set_thread_count(2);
  const TempDir dir;
  const ibms::RunSummary whole = run(scene_for(dir.file("whole.h5")));
  run(scene_for(dir.file("first.h5"), {"run.max_steps=137"}));
  const ibms::RunSummary rest = run(scene_for(dir.file("rest.h5")), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
  ibms::set_thread_count(1);
}

// Rigid and prescribed bodies: the Newton-Euler state and the inner-fluid angular momentum are in the
// checkpoint, the prescribed motion is a function of time; contacts between the two are active.
BOOST_AUTO_TEST_CASE(restarted_run_ends_bit_identical_with_rigid_and_prescribed_bodies) {
  const TempDir dir;
  const auto scene = [&](const std::string& name, std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.begin(), "output.file=" + dir.file(name));
    return ibms::read_scene_file(IBMS_RESTART_SCENE_RIGID, overrides);
  };
  const ibms::RunSummary whole = run(scene("whole.h5"));
  run(scene("first.h5", {"run.max_steps=91"}));
  const ibms::RunSummary rest = run(scene("rest.h5"), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  BOOST_TEST(series_max(dir.file("rest.h5"), "contact/n_active_pairs") > 0.0);
  BOOST_TEST(series_max(dir.file("rest.h5"), "body_000/angular_velocity") != 0.0);
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
  // The control-volume force of the first step after the restart starts from the restored fields.
  for (const char* name : {"body_000/cv_force_x", "body_000/cv_force_y", "body_001/cv_force_x", "body_001/cv_force_y"})
    BOOST_TEST(n_different_series_values(dir.file("whole.h5"), dir.file("rest.h5"), name) == 0u, name);
  BOOST_TEST(series_max(dir.file("rest.h5"), "body_000/cv_force_x") != 0.0);
}

// The adaptive time step (CFL and marker-travel limits) keeps no state of its own: it is a function
// of the restored state, so the restarted run takes the same steps.
BOOST_AUTO_TEST_CASE(restarted_run_with_adaptive_time_step_ends_bit_identical) {
  const TempDir dir;
  const std::vector<std::string> adaptive{"run.time_step=0", "run.cfl=0.1"};
  const ibms::RunSummary whole = run(scene_for(dir.file("whole.h5"), adaptive));
  std::vector<std::string> stopped = adaptive;
  stopped.push_back("run.max_steps=" + std::to_string(whole.steps / 2));
  run(scene_for(dir.file("first.h5"), stopped));
  run(scene_for(dir.file("rest.h5"), adaptive), dir.file("first.h5"));
  // The steps really varied (else this case would repeat the fixed-step one).
  const std::vector<double> dt = series(dir.file("whole.h5"), "dt");
  BOOST_TEST_MESSAGE(whole.steps << " adaptive steps, dt from " << *std::min_element(dt.begin(), dt.end())
                                 << " to " << *std::max_element(dt.begin(), dt.end()));
  BOOST_TEST(*std::max_element(dt.begin(), dt.end()) > 1.5 * *std::min_element(dt.begin(), dt.end()));
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
}

// The collision-time contacts (docs/method.md §5.5) keep no per-contact state: k follows from the
// restored masses and the step's T_c = collision_steps dt, so with the adaptive step (T_c varies)
// the restarted run takes the same steps and ends in the same bits.
BOOST_AUTO_TEST_CASE(restarted_run_with_collision_time_contacts_ends_bit_identical) {
  const TempDir dir;
  // The step capped at 0.01 (after the restart dt = 0.0051-0.0095): at CFL 0.1 alone it grows to ~0.02,
  // T_c = 0.2, and the wheel falling at 0.8 overlaps the wall by ~v0 T_c / pi = 0.05, beyond its CDS
  // radius (0.02), and leaves the box.
  const std::vector<std::string> collision_time{"run.time_step=0", "run.cfl=0.03", "run.max_time_step=0.01",
                                                "contact.model=\"collision_time\"", "contact.stiffness=0"};
  const ibms::RunSummary whole = run(scene_for(dir.file("whole.h5"), collision_time));
  std::vector<std::string> stopped = collision_time;
  stopped.push_back("run.max_steps=" + std::to_string(whole.steps / 2));
  run(scene_for(dir.file("first.h5"), stopped));
  const ibms::RunSummary rest = run(scene_for(dir.file("rest.h5"), collision_time), dir.file("first.h5"));
  BOOST_TEST(rest.steps == whole.steps);
  // Contacts after the restart, with a T_c that varied.
  BOOST_TEST(series_max(dir.file("rest.h5"), "contact/n_active_pairs") > 0.0);
  BOOST_TEST(series_max(dir.file("rest.h5"), "contact/n_wall_contacts") > 0.0);
  const std::vector<double> t_c = series(dir.file("rest.h5"), "contact/collision_time");
  BOOST_TEST(*std::max_element(t_c.begin(), t_c.end()) > 1.2 * *std::min_element(t_c.begin(), t_c.end()));
  BOOST_TEST(n_different_series_values(dir.file("whole.h5"), dir.file("rest.h5"), "contact/max_overlap") == 0u);
  BOOST_TEST(n_different_values(dir.file("whole.h5"), dir.file("rest.h5")) == 0u);
}

BOOST_AUTO_TEST_CASE(checkpoint_carries_the_fftw_planner_wisdom) {
  // Plans are measured, so another process may choose other transforms (round-off differences);
  // the checkpoint stores this process's planner state for `ibms run --restart` to import first.
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  const ibms::Checkpoint checkpoint = ibms::read_checkpoint(dir.file("first.h5"));
  BOOST_REQUIRE(checkpoint.arrays.count("fftw_wisdom") == 1u);
  const std::vector<double>& codes = checkpoint.arrays.at("fftw_wisdom");
  const std::string stored(codes.begin(), codes.end());
  BOOST_TEST(!stored.empty());
  BOOST_TEST(stored == ibms::fft_planner_wisdom());
  BOOST_TEST(ibms::import_fft_planner_wisdom(stored));
  ibms::import_checkpoint_planner_wisdom(checkpoint);  // accepted without throwing
}

BOOST_AUTO_TEST_CASE(checkpoint_of_another_format_version_is_refused) {
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  ibms::Checkpoint checkpoint = ibms::read_checkpoint(dir.file("first.h5"));
  checkpoint.format_version = ibms::checkpoint_format_version + 1;
  ibms::Simulation sim(scene_for(dir.file("x.h5")));
  try {
    ibms::restore_simulation(checkpoint, "first.h5", sim);
    BOOST_FAIL("no InputError");
  } catch (const ibms::InputError& error) {
    BOOST_TEST_MESSAGE(error.what());
    const std::string expected =
        "first.h5: /checkpoint format_version " + std::to_string(ibms::checkpoint_format_version + 1);
    BOOST_TEST(std::string(error.what()).find(expected) == 0u, error.what());
  }
}

BOOST_AUTO_TEST_CASE(corrupted_checkpoint_scalars_and_sizes_are_refused) {
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  const ibms::Checkpoint good = ibms::read_checkpoint(dir.file("first.h5"));
  const auto refused = [&](const ibms::Checkpoint& bad, const std::string& expected) {
    ibms::Simulation sim(scene_for(dir.file("x.h5")));
    try {
      ibms::restore_simulation(bad, "first.h5", sim);
      BOOST_ERROR("no InputError for " << expected);
    } catch (const ibms::InputError& error) {
      BOOST_TEST_MESSAGE(error.what());
      BOOST_TEST(std::string(error.what()).find("first.h5: /checkpoint/" + expected) == 0u, error.what());
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"step", nan}, {"step", 1e300}, {"step", -1.0}, {"step", 2.5}, {"time", -1.0}, {"time", HUGE_VAL},
           {"time_step_prev", nan}, {"next_snapshot_time", nan}, {"nx", 1e19}}) {
    ibms::Checkpoint bad = good;
    bad.scalars[name] = value;
    refused(bad, name);
  }
  ibms::Checkpoint missing = good;
  missing.scalars.erase("time");
  refused(missing, "time");
  ibms::Checkpoint short_array = good;
  short_array.arrays["fluid_pressure"].pop_back();
  refused(short_array, "fluid_pressure");
  ibms::Checkpoint short_body = good;
  short_body.arrays["bodies_position"].resize(4);
  refused(short_body, "bodies_position");
  ibms::Checkpoint odd_count = good;
  odd_count.arrays["bodies_position_count"][1] += 0.5;
  refused(odd_count, "bodies_position_count");
  ibms::Checkpoint moved_values = good;  // the counts add up, body 0 gets body 1's share
  moved_values.arrays["bodies_position_count"][0] += 2;
  moved_values.arrays["bodies_position_count"][1] -= 2;
  refused(moved_values, "bodies_position");
}

BOOST_AUTO_TEST_CASE(restart_with_a_different_scene_or_size_is_refused_and_writes_nothing) {
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  const auto refused = [&](const std::vector<std::string>& overrides, const std::string& expected) {
    const ibms::Scene scene = scene_for(dir.file("second.h5"), overrides);
    try {
      run(scene, dir.file("first.h5"));
      BOOST_ERROR("no InputError for " << expected);
    } catch (const ibms::InputError& error) {
      BOOST_TEST_MESSAGE(error.what());
      BOOST_TEST(std::string(error.what()).find(expected) != std::string::npos, error.what());
      BOOST_TEST(std::string(error.what()).find('\n') == std::string::npos);
    }
    BOOST_TEST(!fs::exists(dir.file("second.h5")));
  };
  refused({"domain.cells_x=16", "domain.cells_y=16"}, "different scene");
  refused({"fluid.kinematic_viscosity=0.03"}, "kinematic_viscosity");
  // [run] and [output] may change: a longer end time is accepted.
  run(scene_for(dir.file("longer.h5"), {"run.end_time=0.02"}), dir.file("first.h5"));
  BOOST_TEST(fs::exists(dir.file("longer.h5")));
}

BOOST_AUTO_TEST_CASE(restart_refuses_to_overwrite_its_own_checkpoint_file) {
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  BOOST_CHECK_THROW(run(scene_for(dir.file("first.h5")), dir.file("first.h5")), ibms::InputError);
  BOOST_TEST(ibms::read_checkpoint(dir.file("first.h5")).scalars.at("step") == 3.0);  // untouched
}

BOOST_AUTO_TEST_CASE(checkpoint_with_an_out_of_range_format_version_is_refused) {
  const TempDir dir;
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  const hid_t f = H5Fopen(dir.file("first.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t g = H5Gopen2(f, "/checkpoint", H5P_DEFAULT);
  const hid_t attribute = H5Aopen(g, "format_version", H5P_DEFAULT);
  const long long huge = 1LL << 40;  // beyond int: the reader must not cast it
  const double huge_double = static_cast<double>(huge);
  const hid_t type = H5Aget_type(attribute);
  if (H5Tget_class(type) == H5T_FLOAT) H5Awrite(attribute, H5T_NATIVE_DOUBLE, &huge_double);
  else H5Awrite(attribute, H5T_NATIVE_LLONG, &huge);
  H5Tclose(type);
  H5Aclose(attribute);
  H5Gclose(g);
  H5Fclose(f);
  BOOST_CHECK_EXCEPTION(ibms::read_checkpoint(dir.file("first.h5")), ibms::InputError, [](const ibms::InputError& e) {
    return std::string(e.what()).find("format_version 1099511627776 is not a version number") != std::string::npos;
  });
}

BOOST_AUTO_TEST_CASE(incomplete_or_missing_checkpoint_is_refused) {
  const TempDir dir;
  BOOST_CHECK_THROW(ibms::read_checkpoint(dir.file("none.h5")), ibms::InputError);
  run(scene_for(dir.file("first.h5"), {"run.max_steps=3"}));
  // Mark it incomplete, as a run killed while writing it leaves it.
  const hid_t f = H5Fopen(dir.file("first.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t g = H5Gopen2(f, "/checkpoint", H5P_DEFAULT);
  const hid_t attribute = H5Aopen(g, "complete", H5P_DEFAULT);
  const hid_t type = H5Aget_type(attribute);
  const long long zero = 0;
  const double zero_double = 0.0;
  if (H5Tget_class(type) == H5T_FLOAT) H5Awrite(attribute, H5T_NATIVE_DOUBLE, &zero_double);
  else H5Awrite(attribute, H5T_NATIVE_LLONG, &zero);
  H5Tclose(type);
  H5Aclose(attribute);
  H5Gclose(g);
  H5Fclose(f);
  BOOST_CHECK_THROW(ibms::read_checkpoint(dir.file("first.h5")), ibms::InputError);
}
