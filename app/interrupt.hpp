// Ctrl-C and SIGTERM during a long command: the first signal asks the command to stop at its
// next sample or frame (it then removes its temporary files, keeps any existing output, and
// exits 130 or 143); a second one removes the temporary files at once and ends the process.
#pragma once

namespace app {

void installInterruptHandlers();
/// The signal received (SIGINT or SIGTERM), or 0.
int interruptSignal();
/// The exit status for it: 128 + the signal number (130 for SIGINT, 143 for SIGTERM).
int interruptedStatus();

}  // namespace app
