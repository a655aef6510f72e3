// One name table per enum: the names a scene file or an option uses, in one place. An enum E
// declares its table by specialising NameTable<E> with a static constexpr array `entries`
// of {value, "name"} pairs; nameOf, parseName and choices read only that table.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rb {

template <typename E>
struct NameTable;  // specialise: static constexpr std::array<std::pair<E, std::string_view>, N>
                   // entries

template <typename E>
constexpr std::string_view nameOf(E value) {
  for (const auto& [v, name] : NameTable<E>::entries)
    if (v == value) return name;
  return "?";
}

template <typename E>
std::optional<E> parseName(std::string_view name) {
  for (const auto& [v, n] : NameTable<E>::entries)
    if (n == name) return v;
  return std::nullopt;
}

/// The names, in the table's order.
template <typename E>
std::vector<std::string_view> namesOf() {
  std::vector<std::string_view> out;
  for (const auto& entry : NameTable<E>::entries) out.push_back(entry.second);
  return out;
}

/// "a, b or c": the names, for messages.
template <typename E>
std::string choices(const char* last_joiner = " or ") {
  std::string out;
  const auto& entries = NameTable<E>::entries;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i > 0) out += i + 1 == entries.size() ? last_joiner : ", ";
    out += entries[i].second;
  }
  return out;
}

}  // namespace rb
