// The output file format (docs/design.md §5): a tiny run (4 x 3 grid, one body of 5 points) with
// three series rows, two snapshots and two checkpoints is written to a temporary directory,
// reopened with the HDF5 C API and checked dataset by dataset. Format, not physics.
#define BOOST_TEST_MODULE output_format
#include <boost/test/unit_test.hpp>

#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_table.hpp"
#include "io/hdf5_handle.hpp"
#include "io/hdf5_objects.hpp"
#include "io/output_file.hpp"

namespace {

namespace fs = std::filesystem;

const ibms::Grid tiny_grid(/*n_x=*/4, /*n_y=*/3, /*lx=*/2.0, /*ly=*/1.5);

// Writes the tiny run once; the directory is removed at exit.
struct TinyRun {
  fs::path directory;
  fs::path h5;
  fs::path xmf;

  TinyRun() {
    std::string pattern = (fs::temp_directory_path() / "ibms_io_test_XXXXXX").string();
    directory = mkdtemp(pattern.data());
    h5 = directory / "out.h5";
    xmf = directory / "out.xmf";
    ibms::OutputFile output(h5.string(), "[run]\nend_time = 1.0\n", tiny_grid, "0.1.0", "abc123");
    output.append_series({{"time", "time", 0.1}, {"dt", "time", 0.1}});
    output.append_series({{"time", "time", 0.2}, {"dt", "time", 0.1}, {"body_000/centroid_x", "length", 0.7}},
                         {{"speed", "length/time", {1.0, 2.0, 3.0}}});
    output.append_series({{"time", "time", 0.3}}, {{"speed", "length/time", {4.0, 5.0, 6.0}}});
    std::vector<double> u(12), p(12), x(5), y(5), vx(5, 0.25);
    for (std::size_t k = 0; k < 12; ++k) u[k] = static_cast<double>(k);
    for (std::size_t k = 0; k < 5; ++k) x[k] = std::cos(k), y[k] = std::sin(k);
    const std::vector<ibms::SnapshotArray> arrays = {
        {"u", "length/time", {3, 4}, u.data()},    {"p", "mass/(length time^2)", {3, 4}, p.data()},
        {"bodies/x", "length", {5}, x.data()},   {"bodies/y", "length", {5}, y.data()},
        {"bodies/vx", "length/time", {5}, vx.data()}};
    output.write_snapshot(10, 0.5, arrays, {2, 3});  // two bodies of 2 and 3 rim points
    output.write_snapshot(20, 1.25, arrays, {2, 3});
    output.write_checkpoint({{"old", {9.0}}}, {{"time", 1.0}}, 1);
    output.write_checkpoint({{"velocity", {1.0, 2.0, 3.0}}, {"empty", {}}}, {{"time", 1.25}, {"step", 20.0}}, 2);
  }
  ~TinyRun() { fs::remove_all(directory); }
};

const TinyRun& tiny_run() {
  static const TinyRun run;
  return run;
}

ibms::Hdf5Handle open_file(const fs::path& path) {
  return ibms::checked_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path, "open");
}

std::vector<hsize_t> dims_of(hid_t file, const std::string& name) {
  const ibms::Hdf5Handle dataset = ibms::checked_handle(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, name, "open");
  const ibms::Hdf5Handle space = ibms::checked_handle(H5Dget_space(dataset.get()), H5Sclose, name, "space");
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

std::vector<double> values_of(hid_t file, const std::string& name) {
  hsize_t n_values = 1;
  for (const hsize_t extent : dims_of(file, name)) n_values *= extent;
  std::vector<double> values(n_values);
  const ibms::Hdf5Handle dataset = ibms::checked_handle(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, name, "open");
  H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  return values;
}

std::string units_of(hid_t file, const std::string& name) {
  const ibms::Hdf5Handle dataset = ibms::checked_handle(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, name, "open");
  return ibms::read_string_attribute(dataset.get(), "units", name);
}

std::string text_of(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Every element closed in order: "<a ...>", "</a>", "<a .../>"; "<?...?>" and "<!...>" skipped.
bool xml_tags_balance(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" />", 1) - (tag[0] == '/' ? 1 : 0));
    if (tag[0] == '/') {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(name);
    }
  }
  return open.empty();
}

}  // namespace

BOOST_AUTO_TEST_CASE(root_attributes_and_grid_datasets_are_written_with_units) {
  const ibms::Hdf5Handle file = open_file(tiny_run().h5);
  for (const char* name : {"ibms_version", "git_commit", "scene", "start_time", "host"}) {
    BOOST_TEST(ibms::has_attribute(file.get(), name), name);
  }
  BOOST_TEST(ibms::read_string_attribute(file.get(), "git_commit", "") == "abc123");
  BOOST_TEST(ibms::read_string_attribute(file.get(), "scene", "") == "[run]\nend_time = 1.0\n");
  BOOST_TEST(ibms::read_string_attribute(file.get(), "start_time", "").back() == 'Z');  // ISO 8601 UTC
  const ibms::Hdf5Handle grid = ibms::checked_handle(H5Gopen2(file.get(), "/grid", H5P_DEFAULT), H5Gclose, "", "grid");
  BOOST_TEST(ibms::read_double_attribute(grid.get(), "nx", "") == 4.0);
  BOOST_TEST(ibms::read_double_attribute(grid.get(), "ny", "") == 3.0);
  BOOST_TEST(values_of(file.get(), "/grid/dx") == std::vector<double>{0.5});
  BOOST_TEST(values_of(file.get(), "/grid/x_faces") == (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  BOOST_TEST(values_of(file.get(), "/grid/y_centres") == (std::vector<double>{0.25, 0.75, 1.25}));
  for (const char* name : {"/grid/dx", "/grid/dy", "/grid/x_centres", "/grid/y_centres", "/grid/x_faces", "/grid/y_faces"}) {
    BOOST_TEST(units_of(file.get(), name) == "length", name);
  }
}

BOOST_AUTO_TEST_CASE(series_extend_by_one_row_per_append_and_stay_aligned) {
  const ibms::Hdf5Handle file = open_file(tiny_run().h5);
  BOOST_TEST(values_of(file.get(), "/series/time") == (std::vector<double>{0.1, 0.2, 0.3}));
  BOOST_TEST(units_of(file.get(), "/series/time") == "time");
  const std::vector<double> dt = values_of(file.get(), "/series/dt");
  BOOST_TEST_REQUIRE(dt.size() == 3u);
  BOOST_TEST((dt[0] == 0.1 && dt[1] == 0.1 && std::isnan(dt[2])));  // row 3 had no dt
  const std::vector<double> centroid = values_of(file.get(), "/series/body_000/centroid_x");
  BOOST_TEST_REQUIRE(centroid.size() == 3u);  // created at row 2: row 1 padded
  BOOST_TEST((std::isnan(centroid[0]) && centroid[1] == 0.7 && std::isnan(centroid[2])));
  BOOST_TEST(units_of(file.get(), "/series/body_000/centroid_x") == "length");
}

BOOST_AUTO_TEST_CASE(per_body_series_are_tables_of_rows_by_bodies_aligned_with_the_rows) {
  const ibms::Hdf5Handle file = open_file(tiny_run().h5);
  BOOST_TEST(dims_of(file.get(), "/series/per_body/speed") == (std::vector<hsize_t>{3, 3}));
  const std::vector<double> speed = values_of(file.get(), "/series/per_body/speed");
  for (int b = 0; b < 3; ++b) BOOST_TEST(std::isnan(speed[b]));  // created at row 2: row 1 padded
  BOOST_TEST((std::vector<double>(speed.begin() + 3, speed.end())) == (std::vector<double>{1, 2, 3, 4, 5, 6}));
  BOOST_TEST(units_of(file.get(), "/series/per_body/speed") == "length/time");
}

BOOST_AUTO_TEST_CASE(a_per_body_series_keeps_its_number_of_columns) {
  std::string pattern = (fs::temp_directory_path() / "ibms_io_test_XXXXXX").string();
  const fs::path directory = mkdtemp(pattern.data());
  {
    ibms::OutputFile output((directory / "out.h5").string(), "", tiny_grid, "0", "0");
    output.append_series({{"time", "time", 0.1}}, {{"speed", "length/time", {1.0, 2.0}}});
    BOOST_CHECK_EXCEPTION(output.append_series({{"time", "time", 0.2}}, {{"speed", "length/time", {1.0}}}),
                          std::exception, [](const std::exception& e) {
                            return std::string(e.what()).find("'speed' has 1 columns, not 2") != std::string::npos;
                          });
  }
  fs::remove_all(directory);
}

BOOST_AUTO_TEST_CASE(snapshots_hold_arrays_with_dims_units_time_and_step) {
  const ibms::Hdf5Handle file = open_file(tiny_run().h5);
  BOOST_TEST(dims_of(file.get(), "/snapshots/000010/u") == (std::vector<hsize_t>{3, 4}));
  BOOST_TEST(values_of(file.get(), "/snapshots/000020/u")[5] == 5.0);  // row-major, x fastest
  BOOST_TEST(units_of(file.get(), "/snapshots/000010/u") == "length/time");
  BOOST_TEST(dims_of(file.get(), "/snapshots/000020/bodies/x") == std::vector<hsize_t>{5});
  BOOST_TEST(units_of(file.get(), "/snapshots/000020/bodies/vx") == "length/time");
  BOOST_TEST(values_of(file.get(), "/snapshots/000020/bodies/first_point") == (std::vector<double>{0, 2, 5}));
  BOOST_TEST(values_of(file.get(), "/snapshots/000020/bodies/body") == (std::vector<double>{0, 1}));
  // XDMF Mixed: polygon (3), its point count, its points.
  BOOST_TEST(values_of(file.get(), "/snapshots/000020/bodies/topology") ==
             (std::vector<double>{3, 2, 0, 1, 3, 3, 2, 3, 4}));
  const ibms::Hdf5Handle snapshot =
      ibms::checked_handle(H5Gopen2(file.get(), "/snapshots/000020", H5P_DEFAULT), H5Gclose, "", "snapshot");
  BOOST_TEST(ibms::read_double_attribute(snapshot.get(), "time", "") == 1.25);
  BOOST_TEST(ibms::read_double_attribute(snapshot.get(), "step", "") == 20.0);
}

BOOST_AUTO_TEST_CASE(a_snapshot_with_bodies_needs_their_rim_coordinates) {
  std::string pattern = (fs::temp_directory_path() / "ibms_io_test_XXXXXX").string();
  const fs::path directory = mkdtemp(pattern.data());
  {
    ibms::OutputFile output((directory / "out.h5").string(), "", tiny_grid, "0", "0");
    const std::vector<double> x(4, 0.5);
    BOOST_CHECK_EXCEPTION(output.write_snapshot(1, 0.1, {{"bodies/x", "length", {4}, x.data()}}, {4}),
                          std::exception, [](const std::exception& e) {
                            return std::string(e.what()).find("bodies/x and bodies/y of 4 points") != std::string::npos;
                          });
  }
  fs::remove_all(directory);
}

BOOST_AUTO_TEST_CASE(read_checkpoint_returns_the_last_checkpoint_written) {
  const ibms::Checkpoint checkpoint = ibms::read_checkpoint(tiny_run().h5.string());
  BOOST_TEST(checkpoint.format_version == 2);
  BOOST_TEST(checkpoint.arrays.size() == 2u);  // "old" from the first checkpoint is gone
  BOOST_TEST(checkpoint.arrays.at("velocity") == (std::vector<double>{1.0, 2.0, 3.0}));
  BOOST_TEST(checkpoint.arrays.at("empty").empty());
  BOOST_TEST(checkpoint.scalars.size() == 2u);
  BOOST_TEST(checkpoint.scalars.at("time") == 1.25);
  BOOST_TEST(checkpoint.scalars.at("step") == 20.0);
  BOOST_TEST(checkpoint.scene == "[run]\nend_time = 1.0\n");
}

BOOST_AUTO_TEST_CASE(xdmf_sidecar_is_balanced_and_lists_both_snapshots) {
  const std::string xml = text_of(tiny_run().xmf);
  BOOST_TEST_MESSAGE(xml.substr(0, 1500));
  BOOST_TEST(xml_tags_balance(xml));
  BOOST_TEST(xml.find("<Xdmf Version=\"3.0\"") != std::string::npos);
  BOOST_TEST(xml.find("CollectionType=\"Temporal\"") != std::string::npos);
  BOOST_TEST(xml.find("<Time Value=\"0.5\"/>") != std::string::npos);
  BOOST_TEST(xml.find("<Time Value=\"1.25\"/>") != std::string::npos);
  BOOST_TEST(xml.find("TopologyType=\"2DRectMesh\" Dimensions=\"4 5\"") != std::string::npos);  // corners
  BOOST_TEST(xml.find("Dimensions=\"3 4\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">out.h5:/snapshots/000010/u<") != std::string::npos);
  BOOST_TEST(xml.find(">out.h5:/snapshots/000020/p<") != std::string::npos);
  BOOST_TEST(xml.find(">out.h5:/grid/x_faces<") != std::string::npos);
  BOOST_TEST(xml.find(">out.h5:/snapshots/000020/bodies/y<") != std::string::npos);
  BOOST_TEST(xml.find("TopologyType=\"Mixed\" NumberOfElements=\"2\"") != std::string::npos);
  BOOST_TEST(xml.find("Dimensions=\"9\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">out.h5:/snapshots/000020/bodies/topology<") !=
             std::string::npos);
  BOOST_TEST(xml.find(">out.h5:/snapshots/000020/bodies/vx<") != std::string::npos);
  BOOST_TEST(xml.find(">out.h5:/snapshots/000020/bodies/body<") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(csv_has_comments_then_header_with_units_then_exact_rows) {
  const fs::path path = tiny_run().directory / "profile.csv";
  ibms::write_csv(path.string(), {"centre-line u", "# Ghia units"}, {"y [length]", "u [length/time]"},
                  {{0.0, 0.5}, {0.1, 1.0 / 3.0}});
  BOOST_TEST(text_of(path) == "# centre-line u\n# Ghia units\ny [length],u [length/time]\n"
                              "0,0.10000000000000001\n0.5,0.33333333333333331\n");
}

BOOST_AUTO_TEST_CASE(failures_throw_input_error_naming_the_path) {
  const std::string missing_directory = "/nonexistent_ibms_dir/out.h5";
  BOOST_CHECK_EXCEPTION(ibms::OutputFile(missing_directory, "", tiny_grid, "0", "0"), ibms::InputError,
                        [&](const ibms::InputError& e) {
                          BOOST_TEST_MESSAGE(e.what());
                          return std::string(e.what()).find(missing_directory) == 0;
                        });
  BOOST_CHECK_THROW(ibms::read_checkpoint(missing_directory), ibms::InputError);
  const fs::path no_checkpoint = tiny_run().directory / "no_checkpoint.h5";
  { ibms::OutputFile output(no_checkpoint.string(), "", tiny_grid, "0", "0"); }
  BOOST_CHECK_EXCEPTION(ibms::read_checkpoint(no_checkpoint.string()), ibms::InputError,
                        [](const ibms::InputError& e) {
                          BOOST_TEST_MESSAGE(e.what());
                          return std::string(e.what()).find("no /checkpoint") != std::string::npos;
                        });
  BOOST_CHECK_THROW(ibms::write_csv((tiny_run().directory / "bad.csv").string(), {}, {"a"}, {{1.0}, {2.0}}),
                    ibms::InputError);
}

// Series rows reach the file in blocks (OutputFile::series_block_rows rows, or series_block_seconds
// after the last block, and at every flush): a process that ends without closing the file (a kill)
// leaves the complete blocks, aligned, and nothing of the rows held back.
BOOST_AUTO_TEST_CASE(series_rows_reach_the_file_in_blocks_and_a_kill_keeps_the_complete_ones) {
  const fs::path dir = fs::temp_directory_path() / ("ibms_series_blocks_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::size_t block = ibms::OutputFile::series_block_rows;
  struct Case { std::size_t rows; bool flush; hsize_t kept; };
  const Case cases[] = {{block - 1, false, 0}, {block + 10, false, block}, {10, true, 10}};
  int k = 0;
  for (const Case& c : cases) {
    const fs::path h5 = dir / ("killed_" + std::to_string(k++) + ".h5");
    const pid_t child = fork();
    if (child == 0) {  // writes, then ends as a killed run would: no destructor, no close
      auto* out = new ibms::OutputFile(h5.string(), "(scene)", tiny_grid, "test", "none");
      for (std::size_t r = 0; r < c.rows; ++r)
        out->append_series({{"step", "-", static_cast<double>(r + 1)}, {"time", "time", 0.1 * (r + 1)}});
      if (c.flush) out->flush();
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    BOOST_TEST_REQUIRE((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    const ibms::Hdf5Handle file = open_file(h5);
    const bool has_series = H5Lexists(file.get(), "/series/step", H5P_DEFAULT) > 0;
    const hsize_t rows = has_series ? dims_of(file.get(), "/series/step")[0] : 0;
    BOOST_TEST_MESSAGE(c.rows << " rows appended" << (c.flush ? " and flushed" : "") << ": " << rows << " in the file");
    BOOST_TEST(rows == c.kept);
    if (has_series) {
      BOOST_TEST(dims_of(file.get(), "/series/time")[0] == rows);
      const std::vector<double> steps = values_of(file.get(), "/series/step");
      for (std::size_t r = 0; r < steps.size(); ++r) BOOST_TEST(steps[r] == static_cast<double>(r + 1));
    }
  }
  fs::remove_all(dir);
}
