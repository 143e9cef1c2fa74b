#include "apps/command_registry.hpp"

#include <unistd.h>

#include <algorithm>
#include <vector>

namespace wifislam::cli {

namespace {
struct Entry {
  std::string name;
  int order;
  CommandSetup setup;
};
std::vector<Entry>& entries() {
  static std::vector<Entry> list;  // function-local: safe during static initialisation
  return list;
}
}  // namespace

bool register_command(const std::string& name, int order, CommandSetup setup) {
  entries().push_back({name, order, std::move(setup)});
  return true;
}

void setup_all_commands(CLI::App& parent) {
  auto list = entries();
  std::sort(list.begin(), list.end(), [](const Entry& a, const Entry& b) {
    return a.order != b.order ? a.order < b.order : a.name < b.name;
  });
  for (const auto& e : list) e.setup(parent);
}

bool stderr_is_tty() { return isatty(STDERR_FILENO) == 1; }

}  // namespace wifislam::cli
