#include "slam/frontend/front_end_registry.hpp"

#include <map>
#include <mutex>

#include "core/error.hpp"
#include "slam/frontend/orbslam/orbslam_front_end.hpp"
#include "slam/frontend/rgbdslam/rgbdslam_front_end.hpp"
#include "slam/frontend/rtabmap/rtabmap_front_end.hpp"

namespace wifislam::slam::frontend {

namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, FrontEndFactory> factories;
};

Registry& registry() {
  // The built-in front ends are listed here, not registered by static initialisers, which a
  // static library would drop when nothing references their object file.
  static Registry* r = [] {
    auto* reg = new Registry;
    reg->factories["rgbdslam"] = [](const FrontEndContext& context) {
      const SlamOptions& o = *context.options;
      return std::make_unique<rgbdslam::RgbdslamFrontEnd>(o.rgbdslam, o.seed);
    };
    reg->factories["orbslam"] = [](const FrontEndContext& context) {
      return std::make_unique<orbslam::OrbslamFrontEnd>(context.options->orbslam);
    };
    reg->factories["rtabmap"] = [](const FrontEndContext& context) {
      const SlamOptions& o = *context.options;
      return std::make_unique<rtabmap::RtabmapFrontEnd>(o.rtabmap, o.graph);
    };
    return reg;
  }();
  return *r;
}

}  // namespace

void register_front_end(const std::string& name, FrontEndFactory factory) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

std::vector<std::string> front_end_names() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [name, factory] : r.factories) names.push_back(name);
  return names;
}

std::unique_ptr<FrontEnd> make_front_end(const FrontEndContext& context) {
  if (context.options == nullptr || context.instrumentation == nullptr) {
    throw InvalidInputError("make_front_end: options and instrumentation are required");
  }
  const SlamOptions& options = *context.options;
  FrontEndFactory factory;
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    const auto it = r.factories.find(options.frontend);
    if (it != r.factories.end()) factory = it->second;
  }
  if (!factory) {
    throw InvalidInputError("unknown SLAM front end '" + options.frontend +
                            "'; known: " + front_end_name_list());
  }
  if (options.wifi.enabled && !context.stream_has_wifi) {
    throw InvalidInputError(
        "the Wi-Fi variant (wifi=true) needs Wi-Fi scans, but the input has none (no wifi.csv, "
        "or one without a scan: a scene without access points); run without --wifi");
  }
  std::unique_ptr<FrontEnd> front_end = factory(context);
  if (options.wifi.enabled) {
    front_end->attach_wifi(
        std::make_unique<wifi::WifiModule>(options.wifi, *context.instrumentation));
  }
  return front_end;
}

std::string front_end_name_list() {
  std::string names;
  for (const std::string& n : front_end_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

}  // namespace wifislam::slam::frontend
