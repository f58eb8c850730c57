// read_checkpoint (checkpoint.hpp): the inverse of OutputFile::write_checkpoint.
#include "io/checkpoint.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "io/hdf5_handle.hpp"
#include "io/hdf5_objects.hpp"

namespace ibms {

namespace {

herr_t collect_name(hid_t, const char* name, const void*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

herr_t collect_link_name(hid_t group, const char* name, const H5L_info_t*, void* names) {
  return collect_name(group, name, nullptr, names);
}

herr_t collect_attribute_name(hid_t object, const char* name, const H5A_info_t*, void* names) {
  return collect_name(object, name, nullptr, names);
}

std::vector<double> read_array(hid_t group, const std::string& name, const std::string& file) {
  const std::string what = fmt::format("cannot read /checkpoint/{}", name);
  const Hdf5Handle dataset = checked_handle(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, file, what);
  const Hdf5Handle space = checked_handle(H5Dget_space(dataset.get()), H5Sclose, file, what);
  if (H5Sget_simple_extent_ndims(space.get()) != 1) throw InputError(fmt::format("{}: {}: not 1-D", file, what));
  hsize_t n_values = 0;
  H5Sget_simple_extent_dims(space.get(), &n_values, nullptr);
  std::vector<double> values(n_values);
  if (n_values > 0) {
    check_hdf5(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), file, what);
  }
  return values;
}

}  // namespace

Checkpoint read_checkpoint(const std::string& h5_path) {
  silence_hdf5_errors();
  if (H5Fis_hdf5(h5_path.c_str()) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    throw InputError(fmt::format("{}: cannot read checkpoint: not a readable HDF5 file", h5_path));
  }
  const Hdf5Handle file = checked_handle(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, h5_path,
                                         "cannot open checkpoint file");
  // /checkpoint, or /checkpoint_next when the run was killed while replacing /checkpoint with it.
  const auto complete_group = [&](const char* name) {
    Hdf5Handle group;
    if (!link_exists(file.get(), name)) return group;
    group = checked_handle(H5Gopen2(file.get(), name, H5P_DEFAULT), H5Gclose, h5_path,
                           fmt::format("cannot open {}", name));
    if (!has_attribute(group.get(), "complete") || read_double_attribute(group.get(), "complete", h5_path) != 1.0)
      group.reset();
    return group;
  };
  Hdf5Handle group = complete_group("/checkpoint");
  if (!group.valid()) group = complete_group("/checkpoint_next");
  if (!group.valid()) {
    if (!link_exists(file.get(), "/checkpoint") && !link_exists(file.get(), "/checkpoint_next"))
      throw InputError(fmt::format("{}: no /checkpoint group (the run wrote no checkpoint)", h5_path));
    throw InputError(fmt::format("{}: /checkpoint is incomplete (the run stopped while writing it)", h5_path));
  }
  Checkpoint checkpoint;
  const double version = read_double_attribute(group.get(), "format_version", h5_path);
  if (!(version >= 0.0 && version <= 1e6 && version == std::floor(version)))  // no UB in the cast below
    throw InputError(fmt::format("{}: /checkpoint format_version {} is not a version number", h5_path, version));
  checkpoint.format_version = static_cast<int>(version);
  if (has_attribute(file.get(), "scene")) checkpoint.scene = read_string_attribute(file.get(), "scene", h5_path);

  std::vector<std::string> attribute_names;
  hsize_t position = 0;
  check_hdf5(H5Aiterate2(group.get(), H5_INDEX_NAME, H5_ITER_INC, &position, collect_attribute_name, &attribute_names),
             h5_path, "cannot list /checkpoint attributes");
  for (const std::string& name : attribute_names) {
    if (name == "complete" || name == "format_version") continue;
    checkpoint.scalars[name] = read_double_attribute(group.get(), name, h5_path);
  }
  std::vector<std::string> array_names;
  position = 0;
  check_hdf5(H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, &position, collect_link_name, &array_names),
             h5_path, "cannot list /checkpoint datasets");
  for (const std::string& name : array_names) checkpoint.arrays[name] = read_array(group.get(), name, h5_path);
  return checkpoint;
}

// CheckpointReader (checkpoint.hpp).
void CheckpointReader::fail(const std::string& name, const std::string& reason) const {
  throw InputError(fmt::format("{}: /checkpoint/{}: {}", path_, name, reason));
}
double CheckpointReader::scalar(const std::string& name) const {
  const auto found = cp_.scalars.find(name);
  if (found == cp_.scalars.end()) fail(name, "missing");
  return found->second;
}
double CheckpointReader::non_negative(const std::string& name) const {
  const double value = scalar(name);
  if (!(std::isfinite(value) && value >= 0.0)) fail(name, fmt::format("must be finite and >= 0, got {}", value));
  return value;
}
long CheckpointReader::count(const std::string& name) const {
  const double value = scalar(name);
  if (!(value >= 0.0 && value <= 9007199254740992.0 && value == std::floor(value)))
    fail(name, fmt::format("must be a whole number >= 0, got {}", value));
  return static_cast<long>(value);
}
const std::vector<double>& CheckpointReader::array(const std::string& name, std::size_t expected_size) const {
  const auto found = cp_.arrays.find(name);
  if (found == cp_.arrays.end()) fail(name, "missing");
  if (found->second.size() != expected_size)
    fail(name, fmt::format("has {} values, this scene needs {}", found->second.size(), expected_size));
  return found->second;
}
const std::vector<double>* CheckpointReader::find(const std::string& name) const {
  const auto found = cp_.arrays.find(name);
  return found == cp_.arrays.end() ? nullptr : &found->second;
}
void CheckpointReader::into(const std::string& name, CellField& field) const {
  const std::vector<double>& values = array(name, static_cast<std::size_t>(field.stride()) * (field.ny() + 2));
  std::copy(values.begin(), values.end(), field.data());
}
void CheckpointReader::into(const std::string& name, FaceField& field) const {
  const std::vector<double>& values = array(name, field.values().size());
  std::copy(values.begin(), values.end(), field.values().begin());
}
void CheckpointReader::into(const std::string& name, std::vector<Vec2>& points) const {
  const std::vector<double>& values = array(name, 2 * points.size());
  for (std::size_t k = 0; k < points.size(); ++k) points[k] = {values[2 * k], values[2 * k + 1]};
}
void CheckpointReader::into(const std::string& name, std::vector<double>& values) const {
  values = array(name, values.size());
}

void append_body_array(std::map<std::string, std::vector<double>>& arrays, const std::string& name, std::size_t body,
                       const std::vector<double>& values) {
  std::vector<double>& counts = arrays[name + "_count"];
  if (counts.size() != body) throw std::logic_error("append_body_array: " + name + " out of body order");
  counts.push_back(static_cast<double>(values.size()));
  std::vector<double>& all = arrays[name];
  all.insert(all.end(), values.begin(), values.end());
}

BodySlice CheckpointReader::body_array(const std::string& name, std::size_t body, std::size_t n_bodies) const {
  auto found = offsets_.find(name);
  if (found == offsets_.end()) {
    const std::string count_name = name + "_count";
    const std::vector<double>& counts = array(count_name, n_bodies);
    std::vector<std::size_t> offset(n_bodies + 1, 0);
    for (std::size_t b = 0; b < n_bodies; ++b) {
      const double c = counts[b];
      if (!(c >= 0.0 && c <= 9007199254740992.0 && c == std::floor(c)))
        fail(count_name, fmt::format("body {}: {} is not a count", b, c));
      offset[b + 1] = offset[b] + static_cast<std::size_t>(c);
    }
    const std::vector<double>* values = find(name);
    if (values == nullptr) fail(name, "missing");
    if (values->size() != offset[n_bodies])
      fail(name, fmt::format("has {} values, its counts add up to {}", values->size(), offset[n_bodies]));
    found = offsets_.emplace(name, std::move(offset)).first;
  }
  const std::vector<std::size_t>& offset = found->second;
  return {cp_.arrays.at(name).data() + offset[body], offset[body + 1] - offset[body]};
}

BodySlice CheckpointReader::body_array(const std::string& name, std::size_t body, std::size_t n_bodies,
                                       std::size_t expected_size) const {
  const BodySlice slice = body_array(name, body, n_bodies);
  if (slice.size != expected_size)
    fail(name, fmt::format("body {} has {} values, this scene needs {}", body, slice.size, expected_size));
  return slice;
}

}  // namespace ibms
