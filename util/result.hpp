// One error convention for sim, scene, render and the app (as Jolt's Result<T>): a function that
// can fail returns Result<T>, the value or an Error; one that returns nothing returns Status.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rb {

/// Why something cannot be done. `key` is the dotted scene key it concerns
/// ("contact.stiffness"), or empty when the message stands alone; `message` says what is
/// wrong and, where it helps, what would be right.
struct Error {
  std::string key;
  std::string message;
  /// For an error in a scene: the file (or the option, or "with_values"), its 1-based line (0
  /// when not in a file) and the dotted key, when known. `message` already names them.
  struct Where {
    std::string file;
    int line = 0;
    std::string key;
  };
  std::optional<Where> where = std::nullopt;
  /// Other dotted keys whose values the message names ("simulation.duration" for a step
  /// count): when one of them was set by an option, the message names that option.
  std::vector<std::string> involves = {};
  /// The machine failed, not the input: OpenGL or the video encoder would not start, a write
  /// failed after its file was opened (a full disk, a file-size limit), memory ran out. The
  /// command line exits 4 for it instead of 2, so that a pipeline can tell a broken runner from
  /// a broken scene (docs/commands.md "Exit codes").
  bool machine = false;
  /// "key message", or the message alone.
  std::string text() const { return key.empty() ? message : key + " " + message; }
};

/// An Error of the machine (`machine` set), with `message`.
inline Error machineError(std::string message) {
  Error e{"", std::move(message)};
  e.machine = true;
  return e;
}

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT: implicit by design
  Result(Error error) : v_(std::move(error)) {}  // NOLINT: implicit by design

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  const Error& error() const { return std::get<1>(v_); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

 private:
  std::variant<T, Error> v_;
};

/// Success, or the error: the result of something that returns nothing.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)) {}  // NOLINT: implicit by design
  static Status fail(std::string message) { return Error{"", std::move(message)}; }
  /// The machine failed (Error::machine).
  static Status fault(std::string message) { return machineError(std::move(message)); }
  bool ok() const { return !error_; }
  explicit operator bool() const { return ok(); }
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

}  // namespace rb
