#pragma once
// Exit codes of the `wifislam` command (documented in README.md).
namespace wifislam::cli {
inline constexpr int kExitBadInput = 2;     // malformed or impossible input (file:line in message)
inline constexpr int kExitIo = 3;           // a file could not be read or written
inline constexpr int kExitEnvironment = 4;  // OSMesa/Embree/... unusable on this machine
inline constexpr int kExitExternal = 5;     // an external system failed (its run folder says why)
inline constexpr int kExitRequirementNotMet = 6;  // eval --require: a requirement is not met
inline constexpr int kExitInternal = 70;          // a bug: please report
}  // namespace wifislam::cli
