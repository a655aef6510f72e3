#include "tasks/output.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace tasks {
namespace fs = std::filesystem;

namespace {

// Temporary files being written, for the signal handler: a fixed table of C strings, so that
// removing them needs no allocation and no lock. A slot is claimed (so that encoders opening
// on threads of their own never take the same one), then written, then marked ready: the
// handler only reads ready slots.
constexpr std::size_t kMaxTemporaries = 16;
constexpr std::size_t kMaxPath = 4096;
enum Slot : int { kFree, kClaimed, kReady };
std::array<char[kMaxPath], kMaxTemporaries> temporaries{};
std::array<std::atomic<int>, kMaxTemporaries> temporary_state{};

}  // namespace

MadeFolders::~MadeFolders() {
  for (auto folder = made_.rbegin(); folder != made_.rend(); ++folder) {
    std::error_code ec;
    if (fs::is_directory(*folder, ec) && fs::is_empty(*folder, ec) && !ec) fs::remove(*folder, ec);
  }
}

rb::Status makeParentFolder(const std::string& path, MadeFolders* made) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return {};
  std::error_code ec;
  if (fs::is_directory(parent, ec)) return {};
  std::vector<fs::path> missing;  // the folders to be made, deepest first
  for (fs::path up = parent; !up.empty() && up != up.parent_path(); up = up.parent_path()) {
    std::error_code e;
    if (fs::exists(fs::symlink_status(up, e))) break;
    missing.push_back(up);
  }
  fs::create_directories(parent, ec);
  if (made)  // also those made before a deeper one failed
    for (auto folder = missing.rbegin(); folder != missing.rend(); ++folder) {
      std::error_code e;
      if (fs::is_directory(*folder, e)) made->add(folder->string());
    }
  if (!ec) return {};
  // A file where a folder of the path should be is the cause to name (its own message,
  // "Not a directory", says neither which nor what to do).
  for (fs::path up = parent; !up.empty() && up != up.parent_path(); up = up.parent_path()) {
    std::error_code e;
    if (fs::exists(up, e) && !fs::is_directory(up, e))
      return rb::Status::fail(path + ": cannot make its folder " + parent.string() + ": " +
                              up.string() + " is a file, not a folder (give " +
                              rb::output_named_by + " another path)");
  }
  return rb::Status::fail(path + ": cannot make its folder " + parent.string() + ": " +
                          ec.message() + " (run from a folder you can write to, or give " +
                          rb::output_named_by + " a path there)");
}

void registerTemporary(const std::string& temp) {
  if (temp.size() >= kMaxPath) return;
  for (std::size_t i = 0; i < kMaxTemporaries; ++i) {
    int expected = kFree;
    if (!temporary_state[i].compare_exchange_strong(expected, kClaimed)) continue;
    std::memcpy(temporaries[i], temp.c_str(), temp.size() + 1);
    temporary_state[i].store(kReady);
    return;
  }
}

void unregisterTemporary(const std::string& temp) {
  for (std::size_t i = 0; i < kMaxTemporaries; ++i)
    if (temporary_state[i].load() == kReady && temp == temporaries[i])
      temporary_state[i].store(kFree);
}

void removeTemporaryFilesNow() {
  for (std::size_t i = 0; i < kMaxTemporaries; ++i)
    if (temporary_state[i].load() == kReady) ::unlink(temporaries[i]);
}

AtomicOutput::AtomicOutput(std::string path, rb::OutputPlace place)
    : path_(std::move(path)), target_(std::move(place.target)), temp_(std::move(place.temporary)) {}

AtomicOutput::AtomicOutput(AtomicOutput&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temp_(std::move(other.temp_)),
      out_(std::move(other.out_)),
      done_(other.done_) {
  other.done_ = true;
}

rb::Result<AtomicOutput> AtomicOutput::open(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status))
    return rb::Error{"", path + ": is a folder, not a file (give " + rb::output_named_by +
                             " a file's name, e.g. one in that folder)"};
  rb::OutputPlace place = rb::outputPlace(path);
  if (auto made = makeParentFolder(place.target); !made) return made.error();
  const bool in_place = place.temporary.empty();
  AtomicOutput file(path, std::move(place));
  file.done_ = in_place;
  errno = 0;
  file.out_.open(in_place ? file.target_ : file.temp_, std::ios::binary | std::ios::trunc);
  if (!file.out_) return rb::Error{"", rb::cannotWriteIn(path, errno)};
  if (!in_place) registerTemporary(file.temp_);
  return file;
}

rb::Status AtomicOutput::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) {
    const std::string reason = std::strerror(errno ? errno : EIO);
    if (!done_) {
      std::remove(temp_.c_str());
      unregisterTemporary(temp_);
    }
    done_ = true;
    return rb::Status::fault(path_ + ": writing failed: " + reason);
  }
  if (done_) return {};
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  done_ = true;
  unregisterTemporary(temp_);
  if (ec) {
    std::remove(temp_.c_str());
    return rb::Status::fault(path_ + ": cannot move the finished file into place: " + ec.message());
  }
  return {};
}

AtomicOutput::~AtomicOutput() {
  if (done_) return;
  out_.close();
  std::remove(temp_.c_str());
  unregisterTemporary(temp_);
}

}  // namespace tasks
