#include "tasks/table.hpp"

#include <charconv>
#include <cmath>

#include "tasks/shortest.hpp"

namespace tasks {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c == '\n' || c == '\r' ? ' ' : c;
  }
  return out + "\"";
}

std::string csvHeader(std::span<const Column> columns) {
  std::string line;
  for (const Column& c : columns) line.append(line.empty() ? "" : ",").append(csvField(c.name));
  return line;
}

nlohmann::json columnsJson(std::span<const Column> columns) {
  nlohmann::json out = nlohmann::json::array();
  for (const Column& c : columns)
    out.push_back({{"name", c.name}, {"unit", c.unit}, {"meaning", c.meaning}});
  return out;
}

char* writeNumber(char* at, double value) {
  if (!std::isfinite(value)) return at;
  // General: fixed when the first digit's exponent is from −4 to 5, else scientific, as %g
  // with its precision 6 chooses (the plain format would write a large whole number with all of
  // its digits, not the shortest). + 0.0: −0 becomes 0.
  return writeShortest(at, value + 0.0);
}

std::string number(std::optional<double> value) {
  if (!value) return "";
  char text[kNumberChars];
  return std::string(text, writeNumber(text, *value));
}

std::string number(std::optional<double> value, int digits) {
  if (!value || !std::isfinite(*value)) return "";
  char text[40];
  // std::to_chars: no locale, no allocation; general format as printf's %.*g.
  const auto end =
      std::to_chars(text, text + sizeof text, *value + 0.0, std::chars_format::general, digits).ptr;
  return std::string(text, end);
}

std::string fixed(std::optional<double> value, int decimals) {
  if (!value || !std::isfinite(*value)) return "";
  char text[400];
  const auto end =
      std::to_chars(text, text + sizeof text, *value + 0.0, std::chars_format::fixed, decimals).ptr;
  return std::string(text, end);
}

}  // namespace tasks
