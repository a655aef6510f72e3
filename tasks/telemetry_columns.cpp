#include "tasks/telemetry_columns.hpp"

#include "util/names.hpp"

namespace tasks {
namespace {

// The index of the sample's contact model in its name table (what the mode column holds).
double modeIndex(const SampleView& v) {
  const auto& names = rb::NameTable<sim::ContactModel>::entries;
  double index = 0;
  while (names[static_cast<std::size_t>(index)].first != v.s.mode) ++index;
  return index;
}

// The header is the CSV's first line (so that every CSV reader takes it as the header); units
// and meanings go to the sidecar X.csv.json.
constexpr TelemetryColumn kTelemetry[] = {
    {{"t", "s", "time"}, ColumnKind::Number, [](const SampleView& v) { return v.s.t; }},
    {{"spin", "rad/s", "n = w.z, + counter-clockwise seen from above"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.spin; }},
    {{"energy", "J", "kinetic + potential + elastic"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.energy; }},
    {{"kinetic", "J", "M v^2/2 + w.L/2"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.kinetic; }},
    {{"potential", "J", "M g z of the centre of mass"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.potential; }},
    {{"elastic", "J", "sum of k depth^2/2 over the contact springs"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.elastic; }},
    {{"tilt_deg", "deg", "angle between the body's z axis and the vertical"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.tilt_deg; }},
    {{"x", "m", "centre of mass"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.x_world.x(); }},
    {{"y", "m", "centre of mass"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.x_world.y(); }},
    {{"z", "m", "centre of mass"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.x_world.z(); }},
    {{"wx", "rad/s", "angular velocity, world axes"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.w_world.x(); }},
    {{"wy", "rad/s", "angular velocity, world axes"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.w_world.y(); }},
    // wz is the spin n = ω·ẑ (sim::telemetryOf).
    {{"wz", "rad/s", "angular velocity, world axes"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.w_world.z(); },
     1},
    {{"Lz", "kg m^2/s", "vertical angular momentum about the centre of mass"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.L_world.z(); }},
    {{"contacts", "", "count of contact points below the floor"},
     ColumnKind::Count,
     [](const SampleView& v) { return static_cast<double>(v.s.contacts); }},
    {{"normal_force", "N", "total normal force of the floor"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.s.normal_force; }},
    {{"mode", "",
      "the contact model integrated: points, smooth or rolling (contact.model auto "
      "switches between rolling and smooth)"},
     ColumnKind::Mode,
     modeIndex},
    {{"qw", "",
      "attitude: unit quaternion (qw, qx, qy, qz), scalar first, rotating body axes into "
      "world axes (world z up); continuous in time (q and -q are the same rotation)"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.q.w(); }},
    {{"qx", "", "attitude quaternion, x part (see qw)"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.q.x(); }},
    {{"qy", "", "attitude quaternion, y part (see qw)"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.q.y(); }},
    {{"qz", "", "attitude quaternion, z part (see qw)"},
     ColumnKind::Number,
     [](const SampleView& v) { return v.q.z(); }},
};

static_assert(std::size(kTelemetry) <= kMaxTelemetryColumns, "raise kMaxTelemetryColumns");

}  // namespace

std::span<const TelemetryColumn> telemetryTable() {
  return kTelemetry;
}

Eigen::Quaterniond attitude(const sim::Telemetry& s) {
  // q and −q are the same rotation; the integrated quaternion is kept as it is (never flipped
  // to qw ≥ 0), so that the columns are continuous in time as the body turns round and round.
  return s.orientation.normalized();
}

}  // namespace tasks
