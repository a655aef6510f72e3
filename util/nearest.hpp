// "Did you mean …?": the known word nearest a mistyped one, for commands, options and scene
// keys alike.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rb {

/// Levenshtein distance between two words.
inline std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The known word nearest `word`, when it is near enough to be a typo of it: at most two edits
/// (a third of the word's letters for a long one) and at most half its letters ("zzz" is no typo
/// of "dz").
template <class Words>
std::optional<std::string> nearestWord(std::string_view word, const Words& known) {
  std::optional<std::string> nearest;
  std::size_t best = 0;
  for (const auto& candidate : known) {
    const std::size_t d = editDistance(word, candidate);
    if (!nearest || d < best) nearest = std::string(candidate), best = d;
  }
  if (nearest && best <= std::max<std::size_t>(2, word.size() / 3) && 2 * best <= word.size())
    return nearest;
  return std::nullopt;
}

}  // namespace rb
