// The tables the commands write (telemetry, sweeps, bench): one CSV dialect (RFC 4180: a header
// line first, a field quoted only when it holds a comma, a quote or a line break, quotes
// doubled), one way to write numbers, and the columns' names and units for the JSON sidecars.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

namespace tasks {

/// A column of a table: its name (the CSV header's) and its unit and meaning (the sidecar's).
struct Column {
  const char* name;
  const char* unit;
};

/// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break, quotes
/// doubled; a line break becomes a space so that every row is one line.
std::string csvField(const std::string& text);

/// The header line of these columns (no newline).
std::string csvHeader(std::span<const Column> columns);

/// The columns as the sidecars list them: [{"name": …, "unit": …}, …].
nlohmann::json columnsJson(std::span<const Column> columns);

/// A number as the tables write it: `digits` significant digits, shortest form (%g-like, no
/// "-0", no locale); empty for none or a non-finite value (what CSV readers take as missing).
std::string number(std::optional<double> value, int digits = 10);
/// A number with `decimals` digits after the point (%.*f-like); empty as for number().
std::string fixed(std::optional<double> value, int decimals);

}  // namespace tasks
