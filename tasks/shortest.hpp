// Doubles as their shortest round-trip text, fast: the numbers of every table and telemetry file.
#pragma once

namespace tasks {

/// Writes the shortest decimal that reads back as exactly `value` (finite), byte for byte as
/// std::to_chars(…, std::chars_format::general) writes it ("-0" for −0); needs 32 characters of
/// room at `at`, as it may write past the end it returns. Returns that end.
char* writeShortest(char* at, double value);

}  // namespace tasks
