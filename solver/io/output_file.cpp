// HDF5 output of one run (output_file.hpp, docs/design.md §5). Series datasets are chunked and
// extendable with fill value NaN, so extending every series by one row and writing only the
// values given leaves NaN where a row had no value.
#include "io/output_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/hdf5_objects.hpp"

namespace ibms {

namespace {

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// "<path without .h5>.xmf"
std::string sidecar_path(const std::string& h5_path) {
  const std::filesystem::path path(h5_path);
  return (path.extension() == ".h5" ? std::filesystem::path(path).replace_extension(".xmf")
                                    : std::filesystem::path(h5_path + ".xmf")).string();
}

constexpr hsize_t series_chunk_rows = 256;  // one chunk per ~256 steps keeps appends cheap

}  // namespace

OutputFile::OutputFile(const std::string& path, const std::string& resolved_scene, const Grid& grid,
                       const std::string& version, const std::string& git_commit)
    : path_(path), xdmf_path_(sidecar_path(path)), grid_(grid) {
  silence_hdf5_errors();
  file_ = checked_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, path,
                         "cannot create HDF5 output file");
  const hid_t root = file_.get();
  write_string_attribute(root, "ibms_version", version, path_);
  write_string_attribute(root, "git_commit", git_commit, path_);
  write_string_attribute(root, "scene", resolved_scene, path_);
  write_string_attribute(root, "start_time", utc_now_iso8601(), path_);
  write_string_attribute(root, "host", host_name(), path_);
  write_grid(grid);
  flush();
}

OutputFile::~OutputFile() {
  try {  // rows held back when a run ends by an exception
    flush();
  } catch (...) {
  }
  series_.clear();  // datasets before the file
  tables_.clear();
  file_.reset();
}

void OutputFile::write_grid(const Grid& grid) {
  const Hdf5Handle group = checked_handle(H5Gcreate2(file_.get(), "/grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                          H5Gclose, path_, "cannot create /grid");
  write_integer_attribute(group.get(), "nx", grid.nx, path_);
  write_integer_attribute(group.get(), "ny", grid.ny, path_);
  write_double_attribute(group.get(), "length_x", grid.length_x, path_);
  write_double_attribute(group.get(), "length_y", grid.length_y, path_);
  write_double_attribute(group.get(), "origin_x", grid.origin_x, path_);
  write_double_attribute(group.get(), "origin_y", grid.origin_y, path_);
  write_integer_attribute(group.get(), "periodic_x", grid.periodic_x ? 1 : 0, path_);
  write_integer_attribute(group.get(), "periodic_y", grid.periodic_y ? 1 : 0, path_);
  const double dx = grid.dx();
  const double dy = grid.dy();
  write_double_dataset(group.get(), "dx", {}, &dx, "length", path_);
  write_double_dataset(group.get(), "dy", {}, &dy, "length", path_);
  std::vector<double> coordinates;
  const auto write_coordinates = [&](const char* name, int n, auto coordinate) {
    coordinates.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) coordinates[static_cast<std::size_t>(i)] = coordinate(i);
    write_double_dataset(group.get(), name, {static_cast<hsize_t>(n)}, coordinates.data(), "length", path_);
  };
  write_coordinates("x_centres", grid.nx, [&](int i) { return grid.x_centre(i); });
  write_coordinates("y_centres", grid.ny, [&](int j) { return grid.y_centre(j); });
  write_coordinates("x_faces", grid.nx + 1, [&](int i) { return grid.x_face(i); });
  write_coordinates("y_faces", grid.ny + 1, [&](int j) { return grid.y_face(j); });
}

hid_t OutputFile::series_dataset(const SeriesValue& value) {
  const auto found = series_.find(value.name);
  if (found != series_.end()) return found->second.get();
  const std::string name = "/series/" + value.name;
  const std::string what = fmt::format("cannot create series '{}'", value.name);
  if (value.name.empty() || link_exists(file_.get(), name)) throw_hdf5_error(path_, what + " (empty or taken name)");
  const hsize_t initial = 0;
  const hsize_t unlimited = H5S_UNLIMITED;
  const Hdf5Handle space = checked_handle(H5Screate_simple(1, &initial, &unlimited), H5Sclose, path_, what);
  const Hdf5Handle creation = checked_handle(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, path_, what);
  check_hdf5(H5Pset_chunk(creation.get(), 1, &series_chunk_rows), path_, what);
  const double missing = std::numeric_limits<double>::quiet_NaN();  // rows without a value
  check_hdf5(H5Pset_fill_value(creation.get(), H5T_NATIVE_DOUBLE, &missing), path_, what);
  const Hdf5Handle link_list = intermediate_group_creation(path_);
  Hdf5Handle dataset = checked_handle(H5Dcreate2(file_.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(),
                                                 link_list.get(), creation.get(), H5P_DEFAULT),
                                      H5Dclose, path_, what);
  write_string_attribute(dataset.get(), "units", value.units, path_);
  const hid_t id = dataset.get();
  series_.emplace(value.name, std::move(dataset));
  return id;
}

OutputFile::Table& OutputFile::series_table(const SeriesColumns& columns) {
  const auto found = tables_.find(columns.name);
  if (found != tables_.end()) {
    if (found->second.width != columns.values.size())
      throw InputError(fmt::format("{}: per-body series '{}' has {} columns, not {}", path_, columns.name,
                                   columns.values.size(), found->second.width));
    return found->second;
  }
  const std::string name = "/series/per_body/" + columns.name;
  const std::string what = fmt::format("cannot create per-body series '{}'", columns.name);
  if (columns.name.empty() || columns.values.empty() || link_exists(file_.get(), name))
    throw_hdf5_error(path_, what + " (empty, no columns or taken name)");
  const hsize_t width = columns.values.size();
  const hsize_t initial[2] = {0, width};
  const hsize_t maximum[2] = {H5S_UNLIMITED, width};
  // About 256 KiB a chunk: rows of many bodies, or series_chunk_rows of a few.
  const hsize_t chunk[2] = {std::clamp<hsize_t>(32768 / width, 1, series_chunk_rows), width};
  const Hdf5Handle space = checked_handle(H5Screate_simple(2, initial, maximum), H5Sclose, path_, what);
  const Hdf5Handle creation = checked_handle(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, path_, what);
  check_hdf5(H5Pset_chunk(creation.get(), 2, chunk), path_, what);
  const double missing = std::numeric_limits<double>::quiet_NaN();
  check_hdf5(H5Pset_fill_value(creation.get(), H5T_NATIVE_DOUBLE, &missing), path_, what);
  const Hdf5Handle link_list = intermediate_group_creation(path_);
  Table table;
  table.dataset = checked_handle(H5Dcreate2(file_.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(), link_list.get(),
                                            creation.get(), H5P_DEFAULT),
                                 H5Dclose, path_, what);
  write_string_attribute(table.dataset.get(), "units", columns.units, path_);
  write_string_attribute(table.dataset.get(), "columns", "body index", path_);
  table.width = columns.values.size();
  return tables_.emplace(columns.name, std::move(table)).first->second;
}

void OutputFile::append_series(const std::vector<SeriesValue>& values, const std::vector<SeriesColumns>& per_body) {
  std::set<std::string> names;
  for (const SeriesValue& value : values) {
    if (!names.insert(value.name).second) {
      throw InputError(fmt::format("{}: series '{}' given twice in one row", path_, value.name));
    }
    series_dataset(value);
  }
  names.clear();
  for (const SeriesColumns& columns : per_body) {
    if (!names.insert(columns.name).second)
      throw InputError(fmt::format("{}: per-body series '{}' given twice in one row", path_, columns.name));
    series_table(columns);
  }
  // This row's value into each of its series' held-back columns; a column that misses rows before
  // it (a series new in this block, or absent from them) is padded with NaN.
  constexpr double missing = std::numeric_limits<double>::quiet_NaN();
  for (const SeriesValue& value : values) {
    std::vector<double>& column = pending_[value.name];
    column.resize(pending_rows_, missing);
    column.push_back(value.value);
  }
  for (const SeriesColumns& columns : per_body) {
    Table& table = tables_.at(columns.name);
    table.pending.resize(pending_rows_ * table.width, missing);
    table.pending.insert(table.pending.end(), columns.values.begin(), columns.values.end());
  }
  ++pending_rows_;
  if (pending_rows_ >= series_block_rows ||
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_series_block_).count() >=
          series_block_seconds)
    flush();
}

void OutputFile::write_pending_series() {
  last_series_block_ = std::chrono::steady_clock::now();
  if (pending_rows_ == 0) return;
  const hsize_t first = n_series_rows_, count = pending_rows_, n_rows = first + count;
  const Hdf5Handle memory = checked_handle(H5Screate_simple(1, &count, nullptr), H5Sclose, path_, "cannot append series");
  for (auto& [name, dataset] : series_) {
    const std::string what = fmt::format("cannot append to series '{}'", name);
    std::vector<double>& column = pending_[name];  // NaN where the block's rows had no value
    column.resize(count, std::numeric_limits<double>::quiet_NaN());
    check_hdf5(H5Dset_extent(dataset.get(), &n_rows), path_, fmt::format("cannot extend series '{}'", name));
    const Hdf5Handle space = checked_handle(H5Dget_space(dataset.get()), H5Sclose, path_, what);
    check_hdf5(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, &first, nullptr, &count, nullptr), path_, what);
    check_hdf5(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, column.data()),
               path_, what);
  }
  for (auto& [name, table] : tables_) {
    const std::string what = fmt::format("cannot append to per-body series '{}'", name);
    table.pending.resize(count * table.width, std::numeric_limits<double>::quiet_NaN());
    const hsize_t extent[2] = {n_rows, table.width}, start[2] = {first, 0}, block[2] = {count, table.width};
    check_hdf5(H5Dset_extent(table.dataset.get(), extent), path_, what);
    const Hdf5Handle rows = checked_handle(H5Screate_simple(2, block, nullptr), H5Sclose, path_, what);
    const Hdf5Handle space = checked_handle(H5Dget_space(table.dataset.get()), H5Sclose, path_, what);
    check_hdf5(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, block, nullptr), path_, what);
    check_hdf5(H5Dwrite(table.dataset.get(), H5T_NATIVE_DOUBLE, rows.get(), space.get(), H5P_DEFAULT,
                        table.pending.data()),
               path_, what);
    table.pending.clear();
  }
  n_series_rows_ = n_rows;
  for (auto& entry : pending_) entry.second.clear();  // capacity kept: no allocation in later blocks
  pending_rows_ = 0;
}

void OutputFile::write_snapshot(long step, double time, const std::vector<SnapshotArray>& arrays,
                                const std::vector<std::size_t>& body_points) {
  if (step < 0) throw InputError(fmt::format("{}: snapshot step {} is negative", path_, step));
  XdmfSnapshot record;
  record.group = fmt::format("/snapshots/{:06d}", step);
  record.time = time;
  const std::string what = fmt::format("cannot write snapshot {}", record.group);
  if (link_exists(file_.get(), record.group)) throw InputError(fmt::format("{}: {}: already written", path_, what));
  std::size_t n_points = 0;
  for (const std::size_t n : body_points) n_points += n;
  const auto has_body_array = [&](const char* name) {
    return std::any_of(arrays.begin(), arrays.end(), [&](const SnapshotArray& a) {
      return a.name == std::string("bodies/") + name && a.dims == std::vector<std::size_t>{n_points};
    });
  };
  if (!body_points.empty() && !(has_body_array("x") && has_body_array("y")))
    throw InputError(fmt::format("{}: {}: bodies/x and bodies/y of {} points are needed", path_, what, n_points));
  const Hdf5Handle link_list = intermediate_group_creation(path_);
  const Hdf5Handle group = checked_handle(
      H5Gcreate2(file_.get(), record.group.c_str(), link_list.get(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose, path_, what);
  write_double_attribute(group.get(), "time", time, path_);
  write_integer_attribute(group.get(), "step", step, path_);
  for (const SnapshotArray& array : arrays) {
    if (array.dims.empty() || array.data == nullptr || array.name.empty()) {
      throw InputError(fmt::format("{}: {}: array '{}' needs a name, dims and data", path_, what, array.name));
    }
    const std::vector<hsize_t> dims(array.dims.begin(), array.dims.end());
    write_double_dataset(group.get(), array.name, dims, array.data, array.units, path_);
    const bool is_grid_field = array.dims.size() == 2 && array.dims[0] == static_cast<std::size_t>(grid_.ny) &&
                               array.dims[1] == static_cast<std::size_t>(grid_.nx);
    if (is_grid_field && array.name.find('/') == std::string::npos) record.cell_arrays.push_back(array.name);
    const bool body_node_array = !body_points.empty() && array.name.rfind("bodies/", 0) == 0 &&
                                 array.dims == std::vector<std::size_t>{n_points};
    if (body_node_array && array.name != "bodies/x" && array.name != "bodies/y")
      record.body_node_arrays.push_back(array.name.substr(7));
  }
  if (!body_points.empty()) {
    std::vector<long long> first{0}, topology;
    std::vector<double> index;
    topology.reserve(2 * body_points.size() + n_points);
    for (std::size_t b = 0; b < body_points.size(); ++b) {
      topology.push_back(3);  // XDMF polygon
      topology.push_back(static_cast<long long>(body_points[b]));
      for (std::size_t k = 0; k < body_points[b]; ++k) topology.push_back(first.back() + static_cast<long long>(k));
      first.push_back(first.back() + static_cast<long long>(body_points[b]));
      index.push_back(static_cast<double>(b));
    }
    write_integer_dataset(group.get(), "bodies/first_point", {first.size()}, first.data(), "-", path_);
    write_integer_dataset(group.get(), "bodies/topology", {topology.size()}, topology.data(), "-", path_);
    write_double_dataset(group.get(), "bodies/body", {index.size()}, index.data(), "-", path_);
    record.n_bodies = body_points.size();
    record.n_body_points = n_points;
    record.topology_size = topology.size();
  }
  flush();
  snapshots_.push_back(std::move(record));
  write_xdmf_sidecar(xdmf_path_, std::filesystem::path(path_).filename().string(), grid_, snapshots_);
}

void OutputFile::write_timing(const std::vector<TimingEntry>& entries) {
  const std::string what = "cannot write /timing";
  if (link_exists(file_.get(), "/timing")) check_hdf5(H5Ldelete(file_.get(), "/timing", H5P_DEFAULT), path_, what);
  Hdf5Handle group =
      checked_handle(H5Gcreate2(file_.get(), "/timing", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, path_, what);
  for (const TimingEntry& e : entries) {
    write_double_dataset(group.get(), e.name, {1}, &e.seconds, "s", path_);
    Hdf5Handle dataset = checked_handle(H5Dopen2(group.get(), e.name.c_str(), H5P_DEFAULT), H5Dclose, path_, what);
    write_integer_attribute(dataset.get(), "calls", e.calls, path_);
  }
  group.reset();
  flush();
}

void OutputFile::write_checkpoint(const std::map<std::string, std::vector<double>>& arrays,
                                  const std::map<std::string, double>& scalars, int format_version) {
  const std::string what = "cannot write /checkpoint";
  for (const auto& [name, value] : scalars) {
    if (name == "format_version" || name == "complete") {
      throw InputError(fmt::format("{}: {}: scalar name '{}' is reserved", path_, what, name));
    }
  }
  // The new checkpoint goes to /checkpoint_next (complete = 0 until everything is on disk), then
  // replaces /checkpoint. A run killed at any moment leaves a complete checkpoint under one of the
  // two names (read_checkpoint takes /checkpoint, else a complete /checkpoint_next).
  if (link_exists(file_.get(), "/checkpoint_next")) {
    check_hdf5(H5Ldelete(file_.get(), "/checkpoint_next", H5P_DEFAULT), path_, what);
  }
  Hdf5Handle group = checked_handle(H5Gcreate2(file_.get(), "/checkpoint_next", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                    H5Gclose, path_, what);
  write_integer_attribute(group.get(), "complete", 0, path_);
  flush();
  write_integer_attribute(group.get(), "format_version", format_version, path_);
  for (const auto& [name, value] : scalars) write_double_attribute(group.get(), name, value, path_);
  for (const auto& [name, values] : arrays) {
    if (name.empty() || name.find('/') != std::string::npos) {
      throw InputError(fmt::format("{}: {}: array name '{}' must be non-empty without '/'", path_, what, name));
    }
    write_double_dataset(group.get(), name, {static_cast<hsize_t>(values.size())}, values.data(), "state", path_);
  }
  flush();
  write_integer_attribute(group.get(), "complete", 1, path_);
  group.reset();
  flush();
  if (link_exists(file_.get(), "/checkpoint")) {
    check_hdf5(H5Ldelete(file_.get(), "/checkpoint", H5P_DEFAULT), path_, what);
    flush();
  }
  check_hdf5(H5Lmove(file_.get(), "/checkpoint_next", file_.get(), "/checkpoint", H5P_DEFAULT, H5P_DEFAULT), path_,
             what);
  flush();
}

void OutputFile::flush() {
  write_pending_series();
  // Buffered writes reach the disk here: a failure is an output failure (disk full), not bad input.
  errno = 0;
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) {
    const int reason = errno;
    H5Eclear2(H5E_DEFAULT);
    throw OutputError(fmt::format("{}: cannot flush the HDF5 output: {}", path_,
                                  reason != 0 ? std::strerror(reason) : "HDF5 write failed"));
  }
}

}  // namespace ibms
