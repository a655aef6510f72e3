#include "tasks/telemetry_arrays.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>

#include "tasks/arrays.hpp"
#include "tasks/telemetry_columns.hpp"
#include "util/names.hpp"

namespace tasks {

TelemetryFormat telemetryFormatOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".npz") return TelemetryFormat::Npz;
  if (ext == ".h5" || ext == ".hdf5") return TelemetryFormat::Hdf5;
  return TelemetryFormat::Csv;
}

const char* formatName(TelemetryFormat format) {
  switch (format) {
    case TelemetryFormat::Npz:
      return "NumPy arrays";
    case TelemetryFormat::Hdf5:
      return "an HDF5 file";
    case TelemetryFormat::Csv:
      break;
  }
  return "a CSV table";
}

const char* extensionOf(TelemetryFormat format) {
  switch (format) {
    case TelemetryFormat::Npz:
      return ".npz";
    case TelemetryFormat::Hdf5:
      return ".h5";
    case TelemetryFormat::Csv:
      break;
  }
  return ".csv";
}

rb::Status checkTelemetryName(const std::string& path, const std::string& named_by) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* other : {".npy", ".mat", ".parquet", ".feather", ".arrow", ".xlsx", ".xls",
                            ".pkl", ".pickle", ".nc", ".hdf", ".he5"})
    if (ext == other)
      return rb::Status::fail(named_by + " " + path +
                              ": writes a CSV table (.csv), NumPy arrays (.npz) or HDF5 (.h5), "
                              "chosen by the name's ending; not " +
                              ext);
  return {};
}

TelemetryArrays::TelemetryArrays() : columns_(telemetryTable().size()) {}

void TelemetryArrays::reserve(std::size_t rows) {
  for (std::vector<double>& c : columns_) c.reserve(rows);
}

void TelemetryArrays::add(const sim::Telemetry& s) {
  const Eigen::Quaterniond q = attitude(s);
  const SampleView view{s, q};
  const auto table = telemetryTable();
  for (std::size_t i = 0; i < table.size(); ++i) columns_[i].push_back(table[i].value(view));
  ++rows_;
}

namespace {

// A column's bytes as its kind is kept: numbers as the doubles themselves, counts as int64, the
// contact model by its name (ASCII, NUL-padded to the longest).
struct ColumnBytes {
  std::vector<std::int64_t> whole;
  std::string words;
};

NamedArray arrayOf(const TelemetryColumn& c, const std::vector<double>& values, ColumnBytes& kept) {
  NamedArray a;
  a.name = c.column.name;
  a.unit = c.column.unit;
  a.meaning = c.column.meaning;
  a.length = values.size();
  switch (c.kind) {
    case ColumnKind::Number:
      a.bytes = {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double)};
      break;
    case ColumnKind::Count:
      a.type = ArrayType::Int64;
      for (double v : values) kept.whole.push_back(static_cast<std::int64_t>(v));
      a.bytes = {reinterpret_cast<const char*>(kept.whole.data()),
                 kept.whole.size() * sizeof(std::int64_t)};
      break;
    case ColumnKind::Mode: {
      const auto& names = rb::NameTable<sim::ContactModel>::entries;
      a.type = ArrayType::Text;
      a.width = 1;
      for (const auto& entry : names) a.width = std::max(a.width, entry.second.size());
      for (double v : values) {
        const std::string_view name = names[static_cast<std::size_t>(v)].second;
        kept.words.append(name).append(a.width - name.size(), '\0');
      }
      a.bytes = kept.words;
      break;
    }
  }
  return a;
}

}  // namespace

rb::Status TelemetryArrays::write(std::ostream& out, TelemetryFormat format,
                                  const std::string& path) const {
  const auto table = telemetryTable();
  std::vector<ColumnBytes> kept(table.size());
  std::vector<NamedArray> arrays;
  for (std::size_t i = 0; i < table.size(); ++i)
    arrays.push_back(arrayOf(table[i], columns_[i], kept[i]));
  if (format == TelemetryFormat::Npz) return writeNpz(out, arrays, path);
  auto image = hdf5Image(arrays, path);
  if (!image) return image.error();
  out.write(image->data(), static_cast<std::streamsize>(image->size()));
  return {};
}

}  // namespace tasks
