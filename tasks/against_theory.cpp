#include "tasks/against_theory.hpp"

#include <array>
#include <utility>

namespace tasks {

AgainstTheory againstTheory(bool preferred, bool reversed, bool either_way) {
  if (!preferred)
    return reversed ? AgainstTheory::NothingToSay : AgainstTheory::KeptAlthoughReversing;
  if (either_way)
    return reversed ? AgainstTheory::ReversedEitherWay : AgainstTheory::KeptAlthoughEitherWay;
  return reversed ? AgainstTheory::ReversedAlthoughPreferred : AgainstTheory::NothingToSay;
}

namespace {

// Each case's words, caption's then note's: the caption goes on from the run's reversals, the
// note from its spin.
using Words = std::pair<std::string_view, std::string_view>;
constexpr std::array<std::pair<AgainstTheory, Words>, 4> kWords{{
    {AgainstTheory::ReversedEitherWay,
     {", as the theory predicts for this body (its rocking grows either way)",
      ", its preferred way, the body reversed too, as the theory predicts for this body (its "
      "rocking grows either way)"}},
    {AgainstTheory::KeptAlthoughEitherWay,
     {": <b>no reversal this way, although the theory's rule of thumb predicts one</b> (its "
      "rocking grows either way, but drag may stop it first; a longer run may show it)",
      ", its preferred way, the body did not reverse within the run, although the theory's rule "
      "of thumb predicts it would (a longer run may show it)"}},
    {AgainstTheory::ReversedAlthoughPreferred,
     {": <b>it reversed although the theory prefers this direction</b> (its rocking grew more "
      "slowly than the other way's, but it grew)",
      " the body reversed although the theory prefers this direction"}},
    {AgainstTheory::KeptAlthoughReversing,
     {": <b>no reversal, although the theory predicts one this way</b> (a longer run may show it)",
      " the body did not reverse within the run"}},
}};

}  // namespace

std::string_view wordsFor(AgainstTheory a, Front front) {
  for (const auto& [which, words] : kWords)
    if (which == a) return front == Front::Caption ? words.first : words.second;
  return "";
}

}  // namespace tasks
