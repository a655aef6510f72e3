#include "app/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace app {
namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(std::string path, std::string temp)
    : path_(std::move(path)), temp_(std::move(temp)) {}

AtomicOutput::AtomicOutput(AtomicOutput&& other) noexcept
    : path_(std::move(other.path_)),
      temp_(std::move(other.temp_)),
      out_(std::move(other.out_)),
      done_(other.done_) {
  other.done_ = true;
}

std::variant<AtomicOutput, std::string> AtomicOutput::open(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) return path + ": is a directory, not a file";
  // A device or pipe (/dev/stdout, /dev/full) is written in place: it cannot be renamed over.
  const bool special = fs::exists(status) && !fs::is_regular_file(status);
  std::string temp = special ? path : path + ".partial-" + std::to_string(::getpid());
  AtomicOutput file(path, temp);
  file.done_ = special;
  file.out_.open(temp, std::ios::binary | std::ios::trunc);
  if (!file.out_) return path + ": cannot write: " + std::strerror(errno);
  return file;
}

std::optional<std::string> AtomicOutput::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) {
    const std::string reason = std::strerror(errno ? errno : EIO);
    if (!done_) std::remove(temp_.c_str());
    done_ = true;
    return path_ + ": writing failed: " + reason;
  }
  if (done_) return std::nullopt;
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  done_ = true;
  if (ec) {
    std::remove(temp_.c_str());
    return path_ + ": cannot move the finished file into place: " + ec.message();
  }
  return std::nullopt;
}

AtomicOutput::~AtomicOutput() {
  if (done_) return;
  out_.close();
  std::remove(temp_.c_str());
}

}  // namespace app
