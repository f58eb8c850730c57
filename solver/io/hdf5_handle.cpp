// HDF5 identifier ownership and error reporting (hdf5_handle.hpp).
#include "io/hdf5_handle.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"

namespace ibms {

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    closer_ = other.closer_;
    other.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Hdf5Handle::reset() {
  if (id_ >= 0 && closer_ != nullptr) closer_(id_);
  id_ = H5I_INVALID_HID;
}

void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

namespace {

// H5E_WALK_UPWARD visits the most specific error first: keep that one.
herr_t keep_innermost(unsigned n, const H5E_error2_t* error, void* client_data) {
  auto* message = static_cast<std::string*>(client_data);
  if (n == 0 && error != nullptr && error->desc != nullptr) *message = error->desc;
  return 0;
}

}  // namespace

void throw_hdf5_error(const std::string& file, const std::string& what) {
  std::string reason;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &reason);
  H5Eclear2(H5E_DEFAULT);
  if (reason.empty()) reason = "HDF5 call failed";
  throw InputError(fmt::format("{}: {}: {}", file, what, reason));
}

Hdf5Handle checked_handle(hid_t id, Hdf5Handle::Closer closer, const std::string& file,
                          const std::string& what) {
  if (id < 0) throw_hdf5_error(file, what);
  return {id, closer};
}

void check_hdf5(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0) throw_hdf5_error(file, what);
}

}  // namespace ibms
