#include "sim/scene/scene.hpp"

#include "core/error.hpp"
#include "core/rng.hpp"

namespace wifislam::sim::scene {

const char* to_string(SpaceKind kind) {
  switch (kind) {
    case SpaceKind::kCorridor:
      return "corridor";
    case SpaceKind::kArea:
      return "area";
    case SpaceKind::kRoom:
      return "room";
  }
  return "unknown";
}

const char* to_string(ApPlacement placement) {
  switch (placement) {
    case ApPlacement::kExplicit:
      return "explicit";
    case ApPlacement::kGrid:
      return "grid";
    case ApPlacement::kRandom:
      return "random";
    case ApPlacement::kRooms:
      return "rooms";
    case ApPlacement::kColinear:
      return "colinear";
  }
  return "unknown";
}

const SceneNode* Scene::find_node(const std::string& id) const {
  for (const auto& n : nodes)
    if (n.id == id) return &n;
  return nullptr;
}

const Corridor* Scene::find_corridor(const std::string& id) const {
  for (const auto& c : corridors)
    if (c.id == id) return &c;
  return nullptr;
}

const Corridor* Scene::corridor_between(const std::string& a, const std::string& b) const {
  for (const auto& c : corridors)
    if ((c.from == a && c.to == b) || (c.from == b && c.to == a)) return &c;
  return nullptr;
}

std::string Scene::where(std::string key_path) const {
  while (true) {
    const auto it = key_locations.find(key_path);
    if (it != key_locations.end()) return it->second;
    const auto cut = key_path.find_last_of(".[");
    if (cut == std::string::npos) break;
    key_path.resize(cut);
  }
  return source_path.empty() ? "scene" : source_path;
}

std::string Scene::key_path_in_file(const std::string& key_path) const {
  // The longest renumbered item the path starts with ("spaces[0]" for "spaces[0].polygon_m").
  for (std::size_t cut = key_path.size(); cut != std::string::npos && cut > 0;
       cut = key_path.find_last_of(".[", cut - 1)) {
    const auto it = key_paths_in_file.find(key_path.substr(0, cut));
    if (it != key_paths_in_file.end()) return it->second + key_path.substr(cut);
  }
  return key_path;
}

void Scene::reject(const std::string& key_path, const std::string& message) const {
  const std::string key = key_path_in_file(key_path);
  // As validate_scene does: a scene built in code has no file to point into.
  if (source_path.empty() && key_locations.empty()) {
    throw InvalidInputError("scene: key '" + key + "': " + message);
  }
  throw ParseError(where(key_path), key, message);
}

radio_model::ReceiverDevice receiver_device(const WifiScannerSpec& spec) {
  if (spec.device) return *spec.device;
  radio_model::ReceiverDevice reference = *radio_model::shipped_device("reference");
  reference.sensitivity_dbm = spec.sensitivity_dbm;
  reference.dwell_per_channel_s = spec.dwell_per_channel_s;
  return reference;
}

const char* to_string(AccessPointChangeKind kind) {
  switch (kind) {
    case AccessPointChangeKind::kOff:
      return "off";
    case AccessPointChangeKind::kMoved:
      return "moved";
    case AccessPointChangeKind::kPower:
      return "power";
    case AccessPointChangeKind::kNew:
      return "new";
  }
  return "unknown";
}

int session_of(const Scene& scene) { return static_cast<int>(scene.session.value_or(0)); }

std::uint64_t session_seed(const Scene& scene) {
  const int session = session_of(scene);
  if (session == 0) return scene.seed;
  return Rng::stream(scene.seed, "session/" + std::to_string(session)).next_u64();
}

}  // namespace wifislam::sim::scene
