#include "study/front_end_choice.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "interop/external_system.hpp"
#include "slam/frontend/front_end_registry.hpp"

namespace wifislam::study {

std::string system_front_end(const std::string& value) {
  const std::vector<std::string> names = slam::frontend::front_end_names();
  if (interop::is_external_frontend(value) ||
      std::find(names.begin(), names.end(), value) != names.end()) {
    return value;
  }
  return interop::kExternalPrefix + value;
}

std::optional<std::string> front_end_problem(const std::string& frontend) {
  if (interop::is_external_frontend(frontend)) {
    try {
      interop::resolve_external_system(frontend);
      return std::nullopt;
    } catch (const Error& e) {
      return std::string(e.what());
    }
  }
  const std::vector<std::string> names = slam::frontend::front_end_names();
  if (std::find(names.begin(), names.end(), frontend) != names.end()) return std::nullopt;
  return fmt::format("unknown front end '{}' (known: {}; or external:NAME|FILE, shipped: {})",
                     frontend, slam::frontend::front_end_name_list(),
                     fmt::join(interop::shipped_system_names(), ", "));
}

std::vector<std::filesystem::path> files_read_by(const slam::SlamOptions& options) {
  std::vector<std::filesystem::path> out;
  if (!options.orbslam.vocabulary.empty()) out.emplace_back(options.orbslam.vocabulary);
  if (std::filesystem::path system = interop::user_system_file(options.frontend); !system.empty())
    out.push_back(std::move(system));
  return out;
}

}  // namespace wifislam::study
