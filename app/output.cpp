#include "app/output.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace app {
namespace fs = std::filesystem;

namespace {

// Temporary files being written, for the signal handler: a fixed table of C strings, so that
// removing them needs no allocation and no lock.
constexpr std::size_t kMaxTemporaries = 16;
constexpr std::size_t kMaxPath = 4096;
std::array<char[kMaxPath], kMaxTemporaries> temporaries{};
std::array<std::atomic<bool>, kMaxTemporaries> temporary_used{};

}  // namespace

std::string temporaryPath(const std::string& path) {
  const fs::path p(path);
  std::string name = ".";
  name += p.filename().string();
  name += ".part-" + std::to_string(::getpid());
  return (p.parent_path() / name).string();
}

rb::Status makeParentFolder(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return {};
  std::error_code ec;
  if (fs::is_directory(parent, ec)) return {};
  fs::create_directories(parent, ec);
  if (ec)
    return rb::Status::fail(path + ": cannot make its folder " + parent.string() + ": " +
                            ec.message() +
                            " (run from a folder you can write to, or give -o a path there)");
  return {};
}

void registerTemporary(const std::string& temp) {
  if (temp.size() >= kMaxPath) return;
  for (std::size_t i = 0; i < kMaxTemporaries; ++i) {
    if (temporary_used[i].load()) continue;
    std::memcpy(temporaries[i], temp.c_str(), temp.size() + 1);
    temporary_used[i].store(true);
    return;
  }
}

void unregisterTemporary(const std::string& temp) {
  for (std::size_t i = 0; i < kMaxTemporaries; ++i)
    if (temporary_used[i].load() && temp == temporaries[i]) temporary_used[i].store(false);
}

void removeTemporaryFilesNow() {
  for (std::size_t i = 0; i < kMaxTemporaries; ++i)
    if (temporary_used[i].load()) ::unlink(temporaries[i]);
}

AtomicOutput::AtomicOutput(std::string path, std::string temp)
    : path_(std::move(path)), temp_(std::move(temp)) {}

AtomicOutput::AtomicOutput(AtomicOutput&& other) noexcept
    : path_(std::move(other.path_)),
      temp_(std::move(other.temp_)),
      out_(std::move(other.out_)),
      done_(other.done_) {
  other.done_ = true;
}

rb::Result<AtomicOutput> AtomicOutput::open(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) return rb::Error{"", path + ": is a folder, not a file"};
  if (auto made = makeParentFolder(path); !made) return made.error();
  // A device or pipe (/dev/stdout, /dev/full) is written in place: it cannot be renamed over.
  const bool special = fs::exists(status) && !fs::is_regular_file(status);
  std::string temp = special ? path : temporaryPath(path);
  AtomicOutput file(path, temp);
  file.done_ = special;
  errno = 0;
  file.out_.open(temp, std::ios::binary | std::ios::trunc);
  if (!file.out_) return rb::Error{"", path + ": cannot write: " + std::strerror(errno ? errno : EACCES)};
  if (!special) registerTemporary(temp);
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
    return rb::Status::fail(path_ + ": writing failed: " + reason);
  }
  if (done_) return {};
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  done_ = true;
  unregisterTemporary(temp_);
  if (ec) {
    std::remove(temp_.c_str());
    return rb::Status::fail(path_ + ": cannot move the finished file into place: " + ec.message());
  }
  return {};
}

AtomicOutput::~AtomicOutput() {
  if (done_) return;
  out_.close();
  std::remove(temp_.c_str());
  unregisterTemporary(temp_);
}

}  // namespace app
