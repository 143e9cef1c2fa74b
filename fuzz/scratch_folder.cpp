#include "fuzz/scratch_folder.hpp"

#include <cstdlib>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace wifislam::fuzz {
namespace {

std::filesystem::path make_process_folder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "wifislam_fuzz_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw EnvironmentError("fuzz: cannot create a scratch folder under " + pattern);
  }
  static std::filesystem::path made;
  made = pattern;
  std::atexit([] {
    std::error_code ec;
    std::filesystem::remove_all(made, ec);
  });
  return made;
}

}  // namespace

const std::filesystem::path& fresh_scratch_folder() {
  static const std::filesystem::path root = make_process_folder();
  static const std::filesystem::path input = root / "input";
  std::filesystem::remove_all(input);  // inside the folder this process made, nothing else
  std::filesystem::create_directory(input);
  return input;
}

}  // namespace wifislam::fuzz
