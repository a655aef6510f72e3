// The one way the command line tells the user anything on standard error (docs/commands.md
// "Messages"): an error's line begins with what it is about (`scenes/x.yaml:12: …`, `--spin: …`,
// `out/x.csv: …`), or `rattleback: ` where it is about nothing the user named; a warning's
// with `rattleback: warning: `, a note's with `rattleback: note: `.
#pragma once

#include <string_view>

namespace app {

/// What a message is: an error (the command ends with its status), a warning (something is
/// likely wrong, and the command goes on) or a note (worth knowing; nothing is wrong).
enum class Tone { Error, Warning, Note };

/// Writes `text` as one line (or more, when it holds newlines) on standard error in `tone`'s
/// style.
void tell(Tone tone, std::string_view text);

}  // namespace app
