// HDF5 through Debian's libhdf5 (its C API, 1.10): a file built in memory with the core driver,
// then taken whole as bytes (H5Fget_file_image), so that it reaches the disk through the same
// whole-or-nothing writer as every other output and a Ctrl-C leaves no half-written file.
//
// The library is opened with dlopen the first time a `.h5` file is written, not linked: linked,
// it and the thirty-odd libraries it needs (libcurl, OpenSSL, Kerberos, LDAP) were mapped into
// every process, a run that writes no HDF5 too, and were most of its start-up (docs/speed.md,
// "Sweeps that stop when their columns are known"). The header gives the functions' types.
#include <dlfcn.h>
#include <hdf5.h>

#include <mutex>
#include <string>
#include <vector>

#include "tasks/arrays.hpp"

namespace tasks {
namespace {

// The functions used here, each as a member of Library of its own type.
#define RATTLEBACK_H5_FUNCTIONS(X) \
  X(H5open)                        \
  X(H5check_version)               \
  X(H5Eset_auto2)                  \
  X(H5Pcreate)                     \
  X(H5Pclose)                      \
  X(H5Pset_fapl_core)              \
  X(H5Pset_obj_track_times)        \
  X(H5Fcreate)                     \
  X(H5Fclose)                      \
  X(H5Fflush)                      \
  X(H5Fget_file_image)             \
  X(H5Tcopy)                       \
  X(H5Tclose)                      \
  X(H5Tset_size)                   \
  X(H5Tset_cset)                   \
  X(H5Tset_strpad)                 \
  X(H5Screate)                     \
  X(H5Screate_simple)              \
  X(H5Sclose)                      \
  X(H5Acreate2)                    \
  X(H5Awrite)                      \
  X(H5Aclose)                      \
  X(H5Dcreate2)                    \
  X(H5Dwrite)                      \
  X(H5Dclose)

// The library's own identifiers of types and property-list classes (what the header's macros
// H5T_C_S1 … read after H5open), each as a member of Library holding the variable's address.
#define RATTLEBACK_H5_VARIABLES(X) \
  X(H5T_C_S1_g)                    \
  X(H5T_IEEE_F64LE_g)              \
  X(H5T_STD_I64LE_g)               \
  X(H5P_CLS_FILE_ACCESS_ID_g)      \
  X(H5P_CLS_DATASET_CREATE_ID_g)

struct Library {
#define RATTLEBACK_H5_MEMBER(name) decltype(&::name) name = nullptr;
  RATTLEBACK_H5_FUNCTIONS(RATTLEBACK_H5_MEMBER)
  RATTLEBACK_H5_VARIABLES(RATTLEBACK_H5_MEMBER)
#undef RATTLEBACK_H5_MEMBER
  std::string error;  ///< why it cannot be used; "" when it can
};

// Opened once for the process and never closed (HDF5 keeps its state until exit).
const Library& h5() {
  static const Library library = [] {
    Library l;
    void* handle = dlopen(RATTLEBACK_HDF5_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      l.error = std::string("writing HDF5 needs the HDF5 library, which could not be opened (") +
                dlerror() + "; Debian: apt-get install libhdf5-103-1), or write .npz or .csv";
      return l;
    }
    std::string missing;
#define RATTLEBACK_H5_LOAD(name)                                     \
  l.name = reinterpret_cast<decltype(l.name)>(dlsym(handle, #name)); \
  if (!l.name) missing += std::string(missing.empty() ? "" : ", ") + #name;
    RATTLEBACK_H5_FUNCTIONS(RATTLEBACK_H5_LOAD)
    RATTLEBACK_H5_VARIABLES(RATTLEBACK_H5_LOAD)
#undef RATTLEBACK_H5_LOAD
    if (!missing.empty()) {
      l.error = std::string(RATTLEBACK_HDF5_SONAME) + " lacks " + missing;
      return l;
    }
    // What the header's macros do before a first call: start the library, then check that it
    // is the version these declarations are (it aborts on a mismatch, as a linked one would).
    if (l.H5open() < 0 || l.H5check_version(H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE) < 0)
      l.error = std::string(RATTLEBACK_HDF5_SONAME) + " could not be started";
    return l;
  }();
  return library;
}

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
bool putText(const Library& h, hid_t object, const char* name, const std::string& text) {
  Id type(h.H5Tcopy(*h.H5T_C_S1_g), h.H5Tclose);
  if (!type.ok() || h.H5Tset_size(type.get(), H5T_VARIABLE) < 0 ||
      h.H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    return false;
  Id space(h.H5Screate(H5S_SCALAR), h.H5Sclose);
  Id attribute(h.H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
               h.H5Aclose);
  const char* value = text.c_str();
  return attribute.ok() && h.H5Awrite(attribute.get(), type.get(), &value) >= 0;
}

// The columns' names in the CSV's order, as a list attribute of the file's root group: its
// datasets are listed by name (h5py sorts them), and this keeps the table's order, as the
// .npz's `columns` array does.
bool putNames(const Library& h, hid_t file, std::span<const NamedArray> arrays) {
  Id type(h.H5Tcopy(*h.H5T_C_S1_g), h.H5Tclose);
  if (!type.ok() || h.H5Tset_size(type.get(), H5T_VARIABLE) < 0 ||
      h.H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    return false;
  std::vector<const char*> names;
  for (const NamedArray& a : arrays) names.push_back(a.name.c_str());
  const hsize_t count = names.size();
  Id space(h.H5Screate_simple(1, &count, nullptr), h.H5Sclose);
  Id attribute(h.H5Acreate2(file, "columns", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
               h.H5Aclose);
  return attribute.ok() && h.H5Awrite(attribute.get(), type.get(), names.data()) >= 0;
}

bool putArray(const Library& h, hid_t file, const NamedArray& a) {
  const hsize_t length = a.length;
  Id space(h.H5Screate_simple(1, &length, nullptr), h.H5Sclose);
  Id text(h.H5Tcopy(*h.H5T_C_S1_g), h.H5Tclose);
  hid_t type = a.type == ArrayType::Float64 ? *h.H5T_IEEE_F64LE_g : *h.H5T_STD_I64LE_g;
  if (a.type == ArrayType::Text) {
    if (h.H5Tset_size(text.get(), a.width) < 0 || h.H5Tset_strpad(text.get(), H5T_STR_NULLPAD) < 0)
      return false;
    type = text.get();
  }
  // No times in the objects' headers (HDF5 records them by default): a run written twice gives
  // the same bytes.
  Id create(h.H5Pcreate(*h.H5P_CLS_DATASET_CREATE_ID_g), h.H5Pclose);
  if (!create.ok() || h.H5Pset_obj_track_times(create.get(), false) < 0) return false;
  Id set(
      h.H5Dcreate2(file, a.name.c_str(), type, space.get(), H5P_DEFAULT, create.get(), H5P_DEFAULT),
      h.H5Dclose);
  if (!set.ok()) return false;
  // (An empty array has nothing to write.)
  if (a.length > 0 &&
      h.H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) < 0)
    return false;
  return putText(h, set.get(), "unit", a.unit) && putText(h, set.get(), "meaning", a.meaning);
}

std::mutex& library() {
  static std::mutex m;  // one file at a time: the error stack switch below is process-wide
  return m;
}

// H5F_ACC_TRUNC's value (H5Fpublic.h): the macro itself calls H5check and H5open, which are
// reached through Library here.
constexpr unsigned kTruncate = 0x0002u;

}  // namespace

rb::Result<std::string> hdf5Image(std::span<const NamedArray> arrays, const std::string& path) {
  const std::lock_guard<std::mutex> lock(library());
  const Library& h = h5();
  if (!h.error.empty()) return rb::Error{"", path + ": " + h.error};
  // The library prints its own error stack on any failure; ours is the one line below.
  h.H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const auto failed = [&] {
    return rb::Error{"", path + ": the HDF5 library could not build the file (out of memory?)"};
  };
  // Grown in one step the size of the data and some room for HDF5's own structures (growing in
  // small steps copied the image over and over); never written to a file of its own.
  std::size_t bytes = 1 << 20;
  for (const NamedArray& a : arrays) bytes += a.bytes.size();
  Id access(h.H5Pcreate(*h.H5P_CLS_FILE_ACCESS_ID_g), h.H5Pclose);
  if (!access.ok() || h.H5Pset_fapl_core(access.get(), bytes, false) < 0) return failed();
  std::string image;
  {
    Id file(h.H5Fcreate("telemetry", kTruncate, H5P_DEFAULT, access.get()), h.H5Fclose);
    if (!file.ok()) return failed();
    for (const NamedArray& a : arrays)
      if (!putArray(h, file.get(), a)) return failed();
    if (!putNames(h, file.get(), arrays)) return failed();
    if (h.H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) return failed();
    const ssize_t size = h.H5Fget_file_image(file.get(), nullptr, 0);
    if (size <= 0) return failed();
    image.resize(static_cast<std::size_t>(size));
    if (h.H5Fget_file_image(file.get(), image.data(), image.size()) != size) return failed();
  }
  return image;
}

}  // namespace tasks
