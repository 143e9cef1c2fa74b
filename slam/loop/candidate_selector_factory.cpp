#include "slam/loop/candidate_selector_factory.hpp"

#include <map>
#include <mutex>

#include "core/error.hpp"
#include "slam/loop/rgbdslam_candidate_selector.hpp"
#include "slam/loop/wifi_rgbdslam_candidate_selector.hpp"

namespace wifislam::slam {

namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, SelectorFactory> factories;
};

Registry& registry() {
  // The built-in front ends are listed here, not registered by static initialisers, which a
  // static library would drop when nothing references their object file.
  static Registry* r = [] {
    auto* reg = new Registry;
    reg->factories["rgbdslam"] = [](const SelectorContext& context) {
      return std::make_unique<RgbdslamCandidateSelector>(context.options->rgbdslam,
                                                         context.options->seed);
    };
    reg->factories["rgbdslam+wifi"] = [](const SelectorContext& context) {
      const SlamOptions& o = *context.options;
      return std::make_unique<WifiRgbdslamCandidateSelector>(
          o.rgbdslam, o.wifi, o.tracking.loop_min_keyframe_gap, o.seed, *context.instrumentation);
    };
    return reg;
  }();
  return *r;
}

}  // namespace

std::string selector_key(const SlamOptions& options) {
  return options.frontend + (options.wifi.enabled ? "+wifi" : "");
}

void register_candidate_selector(const std::string& name, SelectorFactory factory) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

std::vector<std::string> candidate_selector_names() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [name, factory] : r.factories) names.push_back(name);
  return names;
}

std::unique_ptr<CandidateSelector> make_candidate_selector(const SelectorContext& context) {
  if (context.options == nullptr || context.instrumentation == nullptr) {
    throw InvalidInputError("make_candidate_selector: options and instrumentation are required");
  }
  // The Wi-Fi module is a variant of a front end, registered as "<frontend>+wifi".
  const std::string key = selector_key(*context.options);
  if (key.ends_with("+wifi") && !context.stream_has_wifi) {
    throw InvalidInputError(
        "the Wi-Fi variant (wifi=true) needs Wi-Fi scans, but the input has "
        "none (no wifi.csv)");
  }
  SelectorFactory factory;
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    const auto it = r.factories.find(key);
    if (it != r.factories.end()) factory = it->second;
  }
  if (!factory) {
    std::string names;
    for (const std::string& n : candidate_selector_names())
      names += (names.empty() ? "" : ", ") + n;
    throw InvalidInputError("unknown SLAM front end '" + key + "'; known: " + names);
  }
  return factory(context);
}

}  // namespace wifislam::slam
