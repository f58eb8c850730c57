// read_checkpoint (checkpoint.hpp): the inverse of OutputFile::write_checkpoint.
#include "io/checkpoint.hpp"

#include <fmt/format.h>

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

}  // namespace ibms
