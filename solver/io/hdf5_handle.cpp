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

// What the error stack says: its innermost message, whether a write to the file failed, and the
// system's reason of a failed read or write (the "error message = '...'" of HDF5's file driver).
struct ErrorStack {
  std::string innermost;
  std::string system_reason;
  bool write_failed = false;
};

// H5E_WALK_UPWARD visits the most specific error first.
herr_t summarise(unsigned n, const H5E_error2_t* error, void* client_data) {
  auto* stack = static_cast<ErrorStack*>(client_data);
  if (error == nullptr) return 0;
  if (error->min_num == H5E_WRITEERROR || error->min_num == H5E_CANTFLUSH || error->min_num == H5E_NOSPACE)
    stack->write_failed = true;
  if (error->desc == nullptr) return 0;
  const std::string desc = error->desc;
  if (n == 0) stack->innermost = desc;
  const std::string key = "error message = '";
  const auto start = desc.find(key);
  if (stack->system_reason.empty() && start != std::string::npos) {
    const auto end = desc.find('\'', start + key.size());
    if (end != std::string::npos) stack->system_reason = desc.substr(start + key.size(), end - start - key.size());
  }
  return 0;
}

}  // namespace

void throw_hdf5_error(const std::string& file, const std::string& what) {
  ErrorStack stack;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, summarise, &stack);
  H5Eclear2(H5E_DEFAULT);
  // A write that failed (disk full, file size limit) is an output failure, whichever call met it:
  // a dataset or attribute write, a group or dataset creation that evicted cached metadata.
  if (stack.write_failed) {
    throw OutputError(fmt::format("{}: {}: {}", file, what,
                                  stack.system_reason.empty() ? "HDF5 write failed" : stack.system_reason));
  }
  if (stack.innermost.empty()) stack.innermost = "HDF5 call failed";
  throw InputError(fmt::format("{}: {}: {}", file, what, stack.innermost));
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
