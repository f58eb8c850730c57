// Typed HDF5 attributes and datasets (hdf5_objects.hpp).
#include "io/hdf5_objects.hpp"

#include <fmt/format.h>

namespace ibms {

namespace {

Hdf5Handle utf8_string_type(const std::string& file) {
  Hdf5Handle type = checked_handle(H5Tcopy(H5T_C_S1), H5Tclose, file, "cannot create string type");
  check_hdf5(H5Tset_size(type.get(), H5T_VARIABLE), file, "cannot create string type");
  check_hdf5(H5Tset_cset(type.get(), H5T_CSET_UTF8), file, "cannot create string type");
  return type;
}

// Scalar attribute `name` of `type` on `object`, replacing an existing one.
void write_scalar_attribute(hid_t object, const std::string& name, hid_t type, const void* value,
                            const std::string& file) {
  const std::string what = fmt::format("cannot write attribute '{}'", name);
  if (has_attribute(object, name)) check_hdf5(H5Adelete(object, name.c_str()), file, what);
  const Hdf5Handle space = checked_handle(H5Screate(H5S_SCALAR), H5Sclose, file, what);
  const Hdf5Handle attribute = checked_handle(
      H5Acreate2(object, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, file, what);
  check_hdf5(H5Awrite(attribute.get(), type, value), file, what);
}

}  // namespace

void write_string_attribute(hid_t object, const std::string& name, const std::string& value,
                            const std::string& file) {
  const Hdf5Handle type = utf8_string_type(file);
  const char* text = value.c_str();
  write_scalar_attribute(object, name, type.get(), &text, file);
}

void write_double_attribute(hid_t object, const std::string& name, double value, const std::string& file) {
  write_scalar_attribute(object, name, H5T_NATIVE_DOUBLE, &value, file);
}

void write_integer_attribute(hid_t object, const std::string& name, long long value,
                             const std::string& file) {
  write_scalar_attribute(object, name, H5T_NATIVE_LLONG, &value, file);
}

bool has_attribute(hid_t object, const std::string& name) {
  return H5Aexists(object, name.c_str()) > 0;
}

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& file) {
  const std::string what = fmt::format("cannot read string attribute '{}'", name);
  const Hdf5Handle attribute = checked_handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, file, what);
  const Hdf5Handle stored_type = checked_handle(H5Aget_type(attribute.get()), H5Tclose, file, what);
  if (H5Tget_class(stored_type.get()) != H5T_STRING) throw_hdf5_error(file, what + " (not a string)");
  if (H5Tis_variable_str(stored_type.get()) > 0) {
    const Hdf5Handle type = utf8_string_type(file);
    char* text = nullptr;
    check_hdf5(H5Aread(attribute.get(), type.get(), &text), file, what);
    std::string value = text == nullptr ? std::string{} : std::string(text);
    H5free_memory(text);
    return value;
  }
  // Fixed-length string (written by another tool).
  std::string buffer(H5Tget_size(stored_type.get()), '\0');
  check_hdf5(H5Aread(attribute.get(), stored_type.get(), buffer.data()), file, what);
  return buffer.substr(0, buffer.find('\0'));
}

double read_double_attribute(hid_t object, const std::string& name, const std::string& file) {
  const std::string what = fmt::format("cannot read attribute '{}'", name);
  const Hdf5Handle attribute = checked_handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, file, what);
  double value = 0.0;
  check_hdf5(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), file, what);
  return value;
}

Hdf5Handle intermediate_group_creation(const std::string& file) {
  Hdf5Handle list = checked_handle(H5Pcreate(H5P_LINK_CREATE), H5Pclose, file, "cannot create property list");
  check_hdf5(H5Pset_create_intermediate_group(list.get(), 1), file, "cannot create property list");
  return list;
}

namespace {

void write_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims, hid_t file_type,
                   hid_t memory_type, const void* data, const std::string& units, const std::string& file) {
  const std::string what = fmt::format("cannot write dataset '{}'", name);
  const Hdf5Handle space = checked_handle(
      dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
      H5Sclose, file, what);
  const Hdf5Handle link_list = intermediate_group_creation(file);
  const Hdf5Handle dataset = checked_handle(
      H5Dcreate2(location, name.c_str(), file_type, space.get(), link_list.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, file, what);
  hsize_t n_values = 1;
  for (const hsize_t extent : dims) n_values *= extent;
  if (n_values > 0) {
    check_hdf5(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), file, what);
  }
  write_string_attribute(dataset.get(), "units", units, file);
}

}  // namespace

void write_double_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims,
                          const double* data, const std::string& units, const std::string& file) {
  write_dataset(location, name, dims, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, data, units, file);
}

void write_integer_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims,
                           const long long* data, const std::string& units, const std::string& file) {
  write_dataset(location, name, dims, H5T_STD_I64LE, H5T_NATIVE_LLONG, data, units, file);
}

bool link_exists(hid_t location, const std::string& name) {
  // H5Lexists fails (not false) when an intermediate component is missing: check each prefix.
  std::size_t end = 0;
  do {
    end = name.find('/', end + 1);
    const std::string prefix = name.substr(0, end);
    if (!prefix.empty() && prefix != "/" && H5Lexists(location, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  } while (end != std::string::npos);
  return true;
}

}  // namespace ibms
