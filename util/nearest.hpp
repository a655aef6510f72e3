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

/// Edits between two words: letters put in, taken out or changed, and two neighbours swapped (the
/// optimal-string-alignment distance: a swap is one typo, "fsp" for "fps", where counted as two
/// changes it was too far from a three-letter word to be suggested).
inline std::size_t editDistance(std::string_view a, std::string_view b) {
  // Three rows of the table: d[i−2], d[i−1] and d[i].
  std::vector<std::size_t> before(b.size() + 1), last(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) last[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      row[j] =
          std::min({last[j] + 1, row[j - 1] + 1, last[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, last);
    std::swap(last, row);
  }
  return last[b.size()];
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
  // Else the one known word that begins as this one does for five letters or more and three
  // quarters of the shorter: the same word with another ending ("parabola" for "paraboloid").
  std::optional<std::string> begun;
  for (const auto& candidate : known) {
    const std::string_view c(candidate);
    const std::size_t shorter = std::min(word.size(), c.size());
    std::size_t same = 0;
    while (same < shorter && word[same] == c[same]) ++same;
    if (same >= 5 && 4 * same >= 3 * shorter) {
      if (begun) return std::nullopt;  // two such: no guess
      begun = std::string(candidate);
    }
  }
  return begun;
}

}  // namespace rb
