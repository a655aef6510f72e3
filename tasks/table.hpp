// The tables the commands write (telemetry, sweeps, bench): one CSV dialect (RFC 4180: a header
// line first, a field quoted only when it holds a comma, a quote or a line break, quotes
// doubled), one way to write numbers, and the columns' names and units for the JSON sidecars.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>

namespace tasks {

/// A column of a table: its name (the CSV header's), its unit and its meaning (the sidecar's).
/// The unit alone, as a plot's axis label takes it ("rad/s"); "" for a count, a fraction or text.
struct Column {
  const char* name;
  const char* unit;
  const char* meaning;
};

/// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break, quotes
/// doubled; a line break becomes a space so that every row is one line.
std::string csvField(const std::string& text);

/// The header line of these columns (no newline).
std::string csvHeader(std::span<const Column> columns);

/// The columns as the sidecars list them: [{"name": …, "unit": …, "meaning": …}, …].
nlohmann::json columnsJson(std::span<const Column> columns);

/// Room writeNumber needs: the longest shortest form of a double is 24 characters
/// ("-2.2250738585072014e-308").
inline constexpr std::size_t kNumberChars = 32;

/// Writes the shortest text that reads back as exactly `value` (writeShortest: std::to_chars's
/// text, faster; no locale, no allocation), never "-0", at `at`; returns its end. A
/// non-finite value writes nothing (what CSV readers take as missing). JSON (nlohmann's dump)
/// writes the same shortest round-trip digits, so a number reads the same in every output.
char* writeNumber(char* at, double value);

/// A number as the tables write it: writeNumber's text; empty for none or a non-finite value.
std::string number(std::optional<double> value);
/// Rounded to `digits` significant digits, shortest form (%g-like, no "-0", no locale): for
/// measurements (timings) whose further digits are noise.
std::string number(std::optional<double> value, int digits);
/// A number with `decimals` digits after the point (%.*f-like); empty as for number().
std::string fixed(std::optional<double> value, int decimals);

}  // namespace tasks
