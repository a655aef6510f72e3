#include "app/tell.hpp"

#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "app/interrupt.hpp"

namespace app {

void tell(Tone tone, std::string_view text) {
  const char* prefix = tone == Tone::Warning ? "rattleback: warning: "
                       : tone == Tone::Note  ? "rattleback: note: "
                                             : "";
  std::cerr << prefix << text << "\n";
}

int fail(const rb::Error& error) {
  tell(Tone::Error, error.text());
  // A failure of something Ctrl-C stopped (gnuplot ended mid-figure: "interrupted while
  // drawing") is the interruption's: 130 or 143, as a pipeline expects of Ctrl-C.
  if (interruptSignal() != 0) return interruptedStatus();
  return error.machine ? kMachine : kBadInput;
}

}  // namespace app
