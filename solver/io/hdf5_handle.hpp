// RAII ownership of HDF5 identifiers and HDF5 failures turned into exceptions. HDF5's automatic
// printing of its error stack is switched off; the exception carries the file path, what we were
// doing and the reason: an OutputError when a write failed, else an InputError.
#pragma once
#include <hdf5.h>

#include <string>

namespace ibms {

class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = H5I_INVALID_HID; }
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  ~Hdf5Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// Switches off HDF5's printing of error stacks to stderr (idempotent).
void silence_hdf5_errors();

// Throws and clears the HDF5 error stack: OutputError "<file>: <what>: <system's reason>" when a
// write to the file failed (the stack holds a write, flush or file-space error), else InputError
// "<file>: <what>: <innermost HDF5 message>".
[[noreturn]] void throw_hdf5_error(const std::string& file, const std::string& what);

// `id` wrapped with `closer`; throws (as above) when `id` < 0.
Hdf5Handle checked_handle(hid_t id, Hdf5Handle::Closer closer, const std::string& file,
                          const std::string& what);

// Throws (as above) when `status` < 0.
void check_hdf5(herr_t status, const std::string& file, const std::string& what);

}  // namespace ibms
