// Small typed HDF5 operations the output uses: scalar attributes (UTF-8 variable-length strings,
// doubles, integers) and fixed-size double datasets with a `units` attribute (docs/design.md §5:
// every dataset carries its units). All failures throw InputError naming `file`.
#pragma once
#include <hdf5.h>

#include <cstddef>
#include <string>
#include <vector>

#include "io/hdf5_handle.hpp"

namespace ibms {

void write_string_attribute(hid_t object, const std::string& name, const std::string& value,
                            const std::string& file);
void write_double_attribute(hid_t object, const std::string& name, double value, const std::string& file);
void write_integer_attribute(hid_t object, const std::string& name, long long value,
                             const std::string& file);

bool has_attribute(hid_t object, const std::string& name);
std::string read_string_attribute(hid_t object, const std::string& name, const std::string& file);
double read_double_attribute(hid_t object, const std::string& name, const std::string& file);  // converts integers

// Link-creation property list that creates missing intermediate groups ("body_000/x").
Hdf5Handle intermediate_group_creation(const std::string& file);

// A new dataset `name` under `location` with shape `dims` (row-major), filled from `data`.
void write_double_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims,
                          const double* data, const std::string& units, const std::string& file);

// The same for 64-bit integers (index arrays such as an XDMF topology).
void write_integer_dataset(hid_t location, const std::string& name, const std::vector<hsize_t>& dims,
                           const long long* data, const std::string& units, const std::string& file);

bool link_exists(hid_t location, const std::string& name);  // every path component checked

}  // namespace ibms
