// HDF5 through Debian's libhdf5 (its C API, 1.10): a file built in memory with the core driver,
// then taken whole as bytes (H5Fget_file_image), so that it reaches the disk through the same
// whole-or-nothing writer as every other output and a Ctrl-C leaves no half-written file.
#include <hdf5.h>

#include <mutex>
#include <string>

#include "tasks/arrays.hpp"

namespace tasks {
namespace {

// One HDF5 identifier, closed with its own function when it goes.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// A text attribute, variable-length UTF-8: h5py reads it as a str, MATLAB's h5readatt as a char
// array.
bool putText(hid_t object, const char* name, const std::string& text) {
  Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type.ok() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 ||
      H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    return false;
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
               H5Aclose);
  const char* value = text.c_str();
  return attribute.ok() && H5Awrite(attribute.get(), type.get(), &value) >= 0;
}

bool putArray(hid_t file, const NamedArray& a) {
  const hsize_t length = a.length;
  Id space(H5Screate_simple(1, &length, nullptr), H5Sclose);
  Id text(H5Tcopy(H5T_C_S1), H5Tclose);
  hid_t type = a.type == ArrayType::Float64 ? H5T_IEEE_F64LE : H5T_STD_I64LE;
  if (a.type == ArrayType::Text) {
    if (H5Tset_size(text.get(), a.width) < 0 || H5Tset_strpad(text.get(), H5T_STR_NULLPAD) < 0)
      return false;
    type = text.get();
  }
  // No times in the objects' headers (HDF5 records them by default): a run written twice gives
  // the same bytes.
  Id create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!create.ok() || H5Pset_obj_track_times(create.get(), false) < 0) return false;
  Id set(
      H5Dcreate2(file, a.name.c_str(), type, space.get(), H5P_DEFAULT, create.get(), H5P_DEFAULT),
      H5Dclose);
  if (!set.ok()) return false;
  // (An empty array has nothing to write.)
  if (a.length > 0 && H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) < 0)
    return false;
  return putText(set.get(), "unit", a.unit) && putText(set.get(), "meaning", a.meaning);
}

std::mutex& library() {
  static std::mutex m;  // one file at a time: the error stack switch below is process-wide
  return m;
}

}  // namespace

rb::Result<std::string> hdf5Image(std::span<const NamedArray> arrays, const std::string& path) {
  const std::lock_guard<std::mutex> lock(library());
  // The library prints its own error stack on any failure; ours is the one line below.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const auto failed = [&] {
    return rb::Error{"", path + ": the HDF5 library could not build the file (out of memory?)"};
  };
  // Grown in one step the size of the data and some room for HDF5's own structures (growing in
  // small steps copied the image over and over); never written to a file of its own.
  std::size_t bytes = 1 << 20;
  for (const NamedArray& a : arrays) bytes += a.bytes.size();
  Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.ok() || H5Pset_fapl_core(access.get(), bytes, false) < 0) return failed();
  std::string image;
  {
    Id file(H5Fcreate("telemetry", H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose);
    if (!file.ok()) return failed();
    for (const NamedArray& a : arrays)
      if (!putArray(file.get(), a)) return failed();
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) return failed();
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    if (size <= 0) return failed();
    image.resize(static_cast<std::size_t>(size));
    if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) return failed();
  }
  return image;
}

}  // namespace tasks
