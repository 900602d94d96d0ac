/// @file error.hpp
/// @brief The one error type of the toolkit: a message and where it happened.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace tk {

/// A place in the input: file name as the user gave it ("-" shows as
/// "<stdin>") and 1-based line number; line 0 means "no particular line".
struct Location {
  std::string file;
  std::size_t line = 0;
};

/// Thrown for bad data and runtime failures; main turns it into
/// "tool: file:line: message" and exit status 1.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, Location where = {})
      : std::runtime_error(message), where_(std::move(where)) {}

  const Location& where() const noexcept { return where_; }
  /// "file:line: message", "file: message" or just "message".
  std::string located_message() const;

 private:
  Location where_;
};

}  // namespace tk

namespace tk {

/// A bad combination of options found after parsing: exit status 2 and the
/// "Try 'tool --help'" hint, like CLI11's own usage errors.
class UsageError : public Error {
 public:
  using Error::Error;
};

/// The error of a failed system call on `path`: "cannot WHAT: strerror(error)".
Error errno_error(const std::string& path, const std::string& what, int error);

/// Throws Error(message) unless `ok`: how the library checks its settings.
inline void require(bool ok, const std::string& message) {
  if (!ok) throw Error(message);
}

/// Runs `work` and returns what it returns; an Error it throws with no
/// location (the library's checks know no file or line) gets `where`. A
/// UsageError and an Error that has a location pass unchanged.
template <class Work>
auto with_location(const Location& where, const Work& work) -> decltype(work()) {
  try {
    return work();
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    if (!e.where().file.empty() || e.where().line != 0) throw;
    throw Error(e.what(), where);
  }
}

}  // namespace tk
