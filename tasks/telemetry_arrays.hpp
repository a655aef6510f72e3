// The telemetry as arrays, one a column of the table (tasks/telemetry_columns.cpp), for the
// binary files chosen by the output's extension: -o RUN.npz (NumPy) or -o RUN.h5 (HDF5).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sim/telemetry.hpp"
#include "util/result.hpp"

namespace tasks {

enum class TelemetryFormat { Csv, Npz, Hdf5 };

/// By the name's extension, in any case: .npz, .h5 or .hdf5; anything else is CSV.
TelemetryFormat telemetryFormatOf(const std::string& path);
/// As messages name what is written: "a CSV table", "NumPy arrays", "an HDF5 file".
const char* formatName(TelemetryFormat format);
/// The extension a name of that format ends in: ".csv", ".npz", ".h5".
const char* extensionOf(TelemetryFormat format);

/// A name whose extension says a data format not written here (.npy, .mat, .parquet, .xlsx, …)
/// is refused, naming the ones that are: `-o x.npy` had written CSV text that np.load then
/// called pickled data. `named_by` names the output as the caller does ("-o", "to_csv").
rb::Status checkTelemetryName(const std::string& path, const std::string& named_by);

/// A run's columns, gathered sample by sample: each the doubles the CSV writes as text.
class TelemetryArrays {
 public:
  TelemetryArrays();
  void add(const sim::Telemetry& s);
  /// Room for `rows` rows in all: the columns then grow without copying themselves.
  void reserve(std::size_t rows);
  std::size_t rows() const { return rows_; }
  /// Writes them as `format` (Npz or Hdf5) to `out`; `path` names the file in messages.
  rb::Status write(std::ostream& out, TelemetryFormat format, const std::string& path) const;

 private:
  std::vector<std::vector<double>> columns_;  ///< one per row of telemetryTable()
  std::size_t rows_ = 0;
};

}  // namespace tasks
