#pragma once
// Subcommands of `wifislam study` that live in files of their own (command_study.cpp adds them).

#include <CLI/CLI.hpp>

namespace wifislam::cli {

void add_study_slurm_command(CLI::App* app);  // study_slurm_command.cpp
void add_study_place_command(CLI::App* app);  // study_place_command.cpp

}  // namespace wifislam::cli
