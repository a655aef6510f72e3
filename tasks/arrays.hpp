// Named one-dimensional arrays and the two files researchers keep them in: NumPy's .npz and
// HDF5. What `simulate -o RUN.npz` / `-o RUN.h5` and Python's to_npz / to_hdf5 write the
// telemetry's columns as (docs/commands.md "Telemetry as arrays").
#pragma once

#include <cstddef>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "util/result.hpp"

namespace tasks {

enum class ArrayType {
  Float64,  ///< IEEE doubles
  Int64,    ///< signed whole numbers
  Text,     ///< ASCII words of at most `width` characters, NUL-padded
};

/// One array: its name, its unit and meaning (HDF5 attributes; .npz keeps the units in an array of
/// their own), and its items' bytes, little-endian, `width` bytes each (8 for numbers).
struct NamedArray {
  std::string name, unit, meaning;
  ArrayType type = ArrayType::Float64;
  std::size_t length = 0;
  std::size_t width = 8;
  std::string_view bytes;  ///< length × width bytes, owned by the caller
};

/// Writes `arrays` as an uncompressed .npz (a ZIP of NAME.npy, as numpy.savez writes it), with
/// `columns` and `units` arrays of text naming each array and its unit in order. Fails, writing
/// nothing, beyond the 4 GiB a ZIP without its 64-bit extension holds. `path` names the file in
/// messages.
rb::Status writeNpz(std::ostream& out, std::span<const NamedArray> arrays, const std::string& path);

/// An HDF5 file's bytes holding each array as a dataset of its name at the root, with `unit` and
/// `meaning` attributes (h5py: f["t"].attrs["unit"]; MATLAB: h5readatt). Built in memory (HDF5's
/// core driver) so that it reaches the disk through the same whole-or-nothing writer as the CSV.
rb::Result<std::string> hdf5Image(std::span<const NamedArray> arrays, const std::string& path);

}  // namespace tasks
