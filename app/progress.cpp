#include "app/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace app {

namespace {

// A bar redrawn in place, on a terminal that can show one: not TERM=dumb (Emacs' shells, CI runners
// that give a job a pseudo-terminal: only -q, which drops the summary too, silenced it) and not
// with NO_PROGRESS set.
bool terminalTakesABar() {
  if (!::isatty(STDERR_FILENO)) return false;
  const char* term = std::getenv("TERM");
  if (term && std::strcmp(term, "dumb") == 0) return false;
  const char* off = std::getenv("NO_PROGRESS");
  return !(off && *off);
}

}  // namespace

Progress::Progress(std::string label, std::int64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled && terminalTakesABar()),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(std::int64_t done) {
  if (!enabled_ || total_ <= 0) return;
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  std::fprintf(stderr, "\r%s [%.*s%*s] %3.0f%%  ETA %5.1f s ", label_.c_str(), filled,
               "##############################", kWidth - filled, "", 100 * fraction, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 60, "");
  std::fflush(stderr);
}

}  // namespace app
