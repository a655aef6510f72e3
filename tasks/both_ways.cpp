#include "tasks/both_ways.hpp"

#include <cmath>
#include <cstdlib>
#include <map>

namespace tasks {

std::optional<BothWays> bothWays(const scene::Sweep& sweep,
                                 const std::vector<double>& first_reversal_s,
                                 const std::vector<std::optional<bool>>& exports) {
  std::optional<std::size_t> spin;
  for (std::size_t a = 0; a < sweep.axes.size(); ++a)
    if (sweep.axes[a].key == "initial.spin") spin = a;
  if (!spin) return std::nullopt;
  bool negative = false, positive = false;
  for (const std::string& v : sweep.axes[*spin].values) {
    const double value = std::strtod(v.c_str(), nullptr);
    negative |= value < 0;
    positive |= value > 0;
  }
  if (!negative || !positive) return std::nullopt;
  struct Body {
    bool exports = true;  // every row's body exports
    std::vector<std::int64_t> rows;
    // Its first row with a reversal spun each way (clockwise: spin < 0), if any.
    std::optional<std::int64_t> clockwise_row, anticlockwise_row;
  };
  std::map<std::vector<int>, Body> bodies;  // by the coordinates of every other axis
  for (std::int64_t row = 0; row < sweep.rows(); ++row) {
    std::vector<int> at = sweep.coordinates(row);
    const double value = std::strtod(sweep.axes[*spin].values[at[*spin]].c_str(), nullptr);
    at.erase(at.begin() + static_cast<std::ptrdiff_t>(*spin));
    Body& body = bodies[at];
    body.rows.push_back(row);
    const bool reversed = static_cast<std::size_t>(row) < first_reversal_s.size() &&
                          std::isfinite(first_reversal_s[static_cast<std::size_t>(row)]);
    if (!exports.empty() && !(static_cast<std::size_t>(row) < exports.size() &&
                              exports[static_cast<std::size_t>(row)].value_or(false)))
      body.exports = false;
    if (reversed && value < 0 && !body.clockwise_row) body.clockwise_row = row;
    if (reversed && value > 0 && !body.anticlockwise_row) body.anticlockwise_row = row;
  }
  BothWays found;
  found.bodies = static_cast<std::int64_t>(bodies.size());
  // A sweep of spins alone is one body: its first row each way is what to name.
  if (bodies.size() == 1) {
    const Body& body = bodies.begin()->second;
    auto spinOf = [&](std::int64_t row) {
      return sweep.axes[*spin].values[static_cast<std::size_t>(sweep.coordinates(row)[*spin])];
    };
    found.clockwise_row = body.clockwise_row;
    found.anticlockwise_row = body.anticlockwise_row;
    if (body.clockwise_row) found.clockwise_spin = spinOf(*body.clockwise_row);
    if (body.anticlockwise_row) found.anticlockwise_spin = spinOf(*body.anticlockwise_row);
  }
  for (std::size_t a = 0; a < sweep.axes.size(); ++a)
    if (a != *spin) found.other_keys.push_back(sweep.axes[a].key);
  // In the order of the rows: the first body found is the one with the lowest row.
  std::map<std::int64_t, const std::pair<const std::vector<int>, Body>*> by_row;
  for (const auto& entry : bodies) by_row[entry.second.rows.front()] = &entry;
  if (!exports.empty()) found.exporting = 0;
  for (const auto& [row, entry] : by_row) {
    const Body& body = entry->second;
    if (!body.clockwise_row || !body.anticlockwise_row) continue;
    ++found.both;
    if (found.exporting && body.exports) ++*found.exporting;
    // The first that reverses both ways, or where exports is known the first that also exports.
    const bool first = found.exporting ? body.exports && *found.exporting == 1 : found.both == 1;
    if (!first) continue;
    found.first_rows = entry->second.rows;
    for (std::size_t a = 0, k = 0; a < sweep.axes.size(); ++a) {
      if (a == *spin) continue;
      found.first_values.push_back(sweep.axes[a].key + " " +
                                   sweep.axes[a].values[entry->first[k++]]);
    }
  }
  return found;
}

namespace {

// A sweep of spins alone: whether its body reverses both ways, and the first run that reverses
// each way (a list of every row as "the first" body had said nothing).
std::string describeOneBody(const BothWays& found) {
  auto at = [](const std::optional<std::int64_t>& row, const std::string& spin) {
    return "in row " + std::to_string(*row) + " (initial.spin " + spin + ")";
  };
  const bool cw = found.clockwise_row.has_value(), ccw = found.anticlockwise_row.has_value();
  if (cw && ccw) {
    std::string text = "the body reverses both ways: first spun clockwise " +
                       at(found.clockwise_row, found.clockwise_spin) + ", counter-clockwise " +
                       at(found.anticlockwise_row, found.anticlockwise_spin);
    if (found.exporting) text += *found.exporting ? "; it exports a solid" : "; it exports none";
    return text;
  }
  if (cw) return "the body reverses one way only: no run spun counter-clockwise reverses";
  if (ccw) return "the body reverses one way only: no run spun clockwise reverses";
  return "the body reverses neither way in these runs";
}

}  // namespace

std::string describe(const BothWays& found) {
  if (found.other_keys.empty()) return describeOneBody(found);
  // What the groups of rows are: bodies where every other axis is a body's key; else the other
  // axes' settings (a sweep over tilt had called its tilts "bodies").
  std::string keys;
  bool bodies = true;
  for (const std::string& key : found.other_keys) {
    bodies &= key.rfind("body.", 0) == 0;
    keys += (keys.empty() ? "" : " × ") + key;
  }
  const std::string groups = bodies ? (found.bodies == 1 ? " body" : " bodies")
                                    : (found.bodies == 1 ? " setting of " : " settings of ") + keys;
  std::string text = std::to_string(found.both) + " of " + std::to_string(found.bodies) + groups +
                     (found.both == 1 ? " reverses" : " reverse") +
                     " both ways (a first reversal spun each way)";
  if (found.exporting)
    text += ", " + std::to_string(*found.exporting) + " of them exporting a solid";
  if (found.first_rows.empty()) return text;
  text += found.exporting ? "; the first that exports:" : "; the first:";
  for (std::size_t i = 0; i < found.first_values.size(); ++i)
    text += (i ? ", " : " ") + found.first_values[i];
  // Its rows, the first three and the last two where there are more than six (a spin axis of
  // 50 values had listed 50).
  const std::vector<std::int64_t>& rows = found.first_rows;
  text += " (rows";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows.size() > 6 && i == 3) {
      text += ", …";
      i = rows.size() - 2;
    }
    text += (i ? ", " : " ") + std::to_string(rows[i]);
  }
  if (rows.size() > 6) text += ": " + std::to_string(rows.size()) + " rows";
  return text + ")";
}

}  // namespace tasks
