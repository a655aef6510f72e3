// Which bodies of a sweep reverse whichever way they are spun: the rows that differ only in
// initial.spin are one body, and it reverses both ways where a run spun each way has a first
// reversal (docs/getting-started.md "A body that reverses both ways"). The question a maker's
// search asks of its table, answered once for every front end.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/sweep.hpp"

namespace tasks {

struct BothWays {
  std::int64_t bodies = 0;  ///< the bodies: rows alike but for initial.spin
  std::int64_t both = 0;    ///< of them, those with a first reversal spun each way
  /// Of those, the ones `export` writes as a solid (a table with the exports column; else none).
  std::optional<std::int64_t> exporting;
  /// The first such body (the first that exports, where that is known): its other axes' values
  /// ("key value", in the axes' order) and its rows.
  std::vector<std::string> first_values;
  std::vector<std::int64_t> first_rows;
  std::vector<std::string> other_keys;  ///< the axes besides initial.spin, in order
  /// The first body's first row with a reversal spun each way (clockwise: spin < 0), and the
  /// spins of those rows as written: what a sweep of spins alone names.
  std::optional<std::int64_t> clockwise_row, anticlockwise_row;
  std::string clockwise_spin, anticlockwise_spin;
};

/// For a sweep with an initial.spin axis of both signs, which bodies reverse both ways, given
/// each row's first reversal (`first_reversal_s[row]`, NaN for none or a row not ok) and, where
/// the table has the column, whether it exports (`exports[row]`; empty: no column); none for
/// another sweep.
std::optional<BothWays> bothWays(const scene::Sweep& sweep,
                                 const std::vector<double>& first_reversal_s,
                                 const std::vector<std::optional<bool>>& exports = {});

/// One line: "5 of 36 bodies reverse both ways (a first reversal spun each way); the first: …".
std::string describe(const BothWays& found);

}  // namespace tasks
