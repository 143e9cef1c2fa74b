#pragma once
// A per-process scratch folder for targets whose code under test reads files: created once under
// the system temporary folder (mkdtemp), emptied before each input, removed at exit. Only this
// folder, which the process made itself, is ever emptied.

#include <filesystem>

namespace wifislam::fuzz {

/// An empty folder for the next input (the same path every call; its old contents are removed).
const std::filesystem::path& fresh_scratch_folder();

}  // namespace wifislam::fuzz
