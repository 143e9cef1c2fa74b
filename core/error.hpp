#pragma once
// Typed errors raised at the boundaries of the library. Every message is meant for a user:
// it names the file, line and key involved, and says what was expected versus what was found.
// The CLI maps each of these to one line on stderr and a non-zero exit code.

#include <stdexcept>
#include <string>

namespace wifislam {

/// Base of every error the library raises on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file or value the user gave us is malformed (scene file, dataset file, trajectory ...).
/// `where` is "file:line:column" (or as much of it as is known), `key_path` the YAML/CSV key.
class ParseError : public Error {
 public:
  ParseError(std::string where, std::string key_path, std::string message);
  const std::string& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string where_, key_path_, detail_;
};

/// The input is well-formed but describes something impossible (a route through a missing
/// corridor, a disconnected floor plan, a route closer to a wall than allowed ...).
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

/// A file could not be read or written.
class IoError : public Error {
 public:
  using Error::Error;
};

/// A required external facility is missing or unusable (OSMesa cannot create a GL 3.3 context,
/// Embree device creation failed ...).
class EnvironmentError : public Error {
 public:
  using Error::Error;
};

/// An external program the harness ran for the user (a SLAM system of a system file) failed: it
/// did not start, exited non-zero, was killed, timed out, or wrote nothing usable.
class ExternalSystemError : public Error {
 public:
  using Error::Error;
};

/// The evaluation ran, but a requirement the user set on it (`eval --require`) is not met: the
/// harness used as a regression test says the system under test regressed.
class RequirementNotMetError : public Error {
 public:
  using Error::Error;
};

}  // namespace wifislam
