// `wifislam`: the command line of the harness. Thin: parses arguments, calls the libraries,
// and maps typed errors to one clear line on stderr and a non-zero exit code.

#include <csignal>
#include <cstdio>
#include <exception>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "apps/command_registry.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/stop_signal.hpp"
#include "core/thread_start.hpp"
#include "core/utf8.hpp"

int main(int argc, char** argv) {
  wifislam::cap_default_thread_stack();
  CLI::App app{
      "wifislam: synthetic indoor worlds, off-screen RGB-D rendering, simulated Wi-Fi, and visual\n"
      "SLAM with and without Wi-Fi augmentation, scored against exact ground truth."};
  app.set_version_flag("--version", std::string("wifislam ") + WIFISLAM_VERSION);
  app.require_subcommand(1);
  wifislam::cli::setup_all_commands(app);
  // Paths and settings end up in JSON files, which hold UTF-8 only: a Latin-1 file name failed
  // as an internal error when the first of them was written, after the work.
  for (int i = 1; i < argc; ++i) {
    if (!wifislam::is_valid_utf8(argv[i])) {
      fmt::print(stderr,
                 "wifislam: error: argument {} is not valid UTF-8 (a file name in another "
                 "encoding?): the outputs record paths and settings as UTF-8; rename it\n",
                 i);
      return wifislam::cli::kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const wifislam::StoppedBySignal& e) {
    // The work unwound and removed its unfinished output; the process then ends by the signal,
    // as the caller (a shell, a script's `wait`) expects of a program stopped by one.
    fmt::print(stderr, "wifislam: {}\n", e.what());
    std::fflush(stderr);
    std::signal(e.signal(), SIG_DFL);
    std::raise(e.signal());
    return 128 + e.signal();
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the usage message; --help and --version are its "errors" with code 0. Any
    // other argument error is bad input, with the tool's one code for it.
    const int code = app.exit(e);
    return code == 0 ? 0 : wifislam::cli::kExitBadInput;
  } catch (const wifislam::ParseError& e) {
    fmt::print(stderr, "wifislam: error: {}\n", e.what());
    return wifislam::cli::kExitBadInput;
  } catch (const wifislam::InvalidInputError& e) {
    fmt::print(stderr, "wifislam: error: {}\n", e.what());
    return wifislam::cli::kExitBadInput;
  } catch (const wifislam::IoError& e) {
    fmt::print(stderr, "wifislam: error: {}\n", e.what());
    return wifislam::cli::kExitIo;
  } catch (const wifislam::EnvironmentError& e) {
    fmt::print(stderr, "wifislam: error: {}\n", e.what());
    return wifislam::cli::kExitEnvironment;
  } catch (const wifislam::ExternalSystemError& e) {
    fmt::print(stderr, "wifislam: error: {}\n", e.what());
    return wifislam::cli::kExitExternal;
  } catch (const wifislam::RequirementNotMetError& e) {
    fmt::print(stderr, "wifislam: {}\n", e.what());
    return wifislam::cli::kExitRequirementNotMet;
  } catch (const std::exception& e) {
    fmt::print(stderr, "wifislam: internal error: {}\n", e.what());
    return wifislam::cli::kExitInternal;
  }
  return 0;
}
