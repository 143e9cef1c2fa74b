#pragma once
// Subcommands register themselves here so main.cpp stays a thin dispatcher.
//
//   WIFISLAM_COMMAND(world, 20) { ... CLI::App& app = *parent.add_subcommand(...); ... }
//
// `order` sets the position in `wifislam --help`.

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace wifislam::cli {

using CommandSetup = std::function<void(CLI::App& parent)>;

bool register_command(const std::string& name, int order, CommandSetup setup);
void setup_all_commands(CLI::App& parent);

/// True when stderr is a terminal (progress bars and colours only then).
bool stderr_is_tty();

}  // namespace wifislam::cli

#define WIFISLAM_COMMAND(name, order)                                                  \
  static void wifislam_setup_command_##name(CLI::App& parent);                         \
  [[maybe_unused]] static const bool wifislam_command_registered_##name =              \
      ::wifislam::cli::register_command(#name, order, &wifislam_setup_command_##name); \
  static void wifislam_setup_command_##name(CLI::App& parent)
