// The telemetry's columns, declared once: each one's name, unit and meaning (a tasks::Column)
// and how it is read from a sample. The CSV writer, the sidecar, Python's arrays, the bench and
// the report's reader all loop over this table, so a new column is one row here
// (docs/commands.md "The telemetry CSV" lists them for the reader).
#pragma once

#include <Eigen/Geometry>
#include <span>

#include "sim/telemetry.hpp"
#include "tasks/table.hpp"

namespace tasks {

/// A sample as the columns read it: the sample and its attitude (attitude(), made once a row).
struct SampleView {
  const sim::Telemetry& s;
  const Eigen::Quaterniond& q;
};

/// What a column holds, which says how it is written and which array Python gives.
enum class ColumnKind {
  Number,  ///< a double, written as its shortest round-trip text; float64 in Python
  Count,   ///< a whole number (value() gives it exactly); int64 in Python
  Mode,    ///< the contact model's name; value() gives its index in NameTable<ContactModel>
};

struct TelemetryColumn {
  Column column;  ///< name, unit (the sidecar's), meaning (the sidecar's)
  ColumnKind kind = ColumnKind::Number;
  double (*value)(const SampleView&) = nullptr;  ///< the column's value at a sample
  /// A column that equals another one's value by construction (wz is the spin n = ω·ẑ): when the
  /// two doubles have the same bits, the CSV copies that column's text rather than formatting it
  /// again. -1 for none; otherwise an earlier column's index.
  int same_as = -1;
};

/// The most columns a row has room for (the writer's buffers; a static_assert holds the table to
/// it).
inline constexpr std::size_t kMaxTelemetryColumns = 24;

/// Every column of the telemetry, in the CSV's order.
std::span<const TelemetryColumn> telemetryTable();

/// The body's attitude at a sample as the qw … qz columns give it: unit, scalar first, body to
/// world, continuous in time (the integrated quaternion, never flipped).
Eigen::Quaterniond attitude(const sim::Telemetry& s);

}  // namespace tasks
