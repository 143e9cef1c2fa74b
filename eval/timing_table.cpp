#include "eval/timing_table.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace wifislam::eval {

namespace {
constexpr const char* kWifiClustering = "wifi_clustering";
constexpr const char* kWifiClusterManagement = "wifi_cluster_management";
}  // namespace

nlohmann::ordered_json TimingTable::to_json() const {
  nlohmann::ordered_json j;
  j["loop_closure_detection_s"] = loop_closure_detection_s;
  j["candidate_selection_s"] = candidate_selection_s;
  j["wifi_clustering_s"] = wifi_clustering_s;
  j["wifi_cluster_management_s"] = wifi_cluster_management_s;
  j["wifi_overhead_s"] = wifi_overhead_s;
  j["optimisation_s"] = optimisation_s;
  j["total_s"] = total_s;
  j["wall_s"] = wall_s;
  for (const auto& [name, m] : modules) {
    j["modules"][name] = {{"total_s", m.total_s}, {"calls", m.calls}};
  }
  j["counters"] = nlohmann::ordered_json::object();
  for (const auto& [name, v] : counters) j["counters"][name] = v;
  return j;
}

TimingTable read_timing_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path.string() + ": cannot read");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw ParseError(path.string(), "", std::string("not valid JSON: ") + e.what());
  }
  const std::string file = path.string();
  auto number = [&](const nlohmann::json& v, const std::string& key) {
    if (!v.is_number()) throw ParseError(file, key, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < 0) throw ParseError(file, key, "expected a finite value >= 0");
    return x;
  };
  if (!j.is_object()) throw ParseError(file, "", "expected a JSON object");
  TimingTable t;
  if (j.contains("modules")) {
    if (!j["modules"].is_object()) throw ParseError(file, "modules", "expected an object");
    for (const auto& [name, m] : j["modules"].items()) {
      const std::string key = "modules." + name;
      if (!m.is_object() || !m.contains("total_s")) {
        throw ParseError(file, key, "expected {\"total_s\": ..., \"calls\": ...}");
      }
      ModuleTiming mt;
      mt.total_s = number(m["total_s"], key + ".total_s");
      if (m.contains("calls")) {
        mt.calls = static_cast<std::int64_t>(number(m["calls"], key + ".calls"));
      }
      t.modules[name] = mt;
    }
  }
  if (j.contains("counters")) {
    if (!j["counters"].is_object()) throw ParseError(file, "counters", "expected an object");
    for (const auto& [name, v] : j["counters"].items()) {
      t.counters[name] = static_cast<std::int64_t>(number(v, "counters." + name));
    }
  }
  if (j.contains("wall_s")) t.wall_s = number(j["wall_s"], "wall_s");
  auto module_s = [&](const char* name) {
    const auto it = t.modules.find(name);
    return it == t.modules.end() ? 0.0 : it->second.total_s;
  };
  t.loop_closure_detection_s = module_s("loop_closure_detection");
  t.candidate_selection_s = module_s("candidate_selection");
  t.wifi_clustering_s = module_s(kWifiClustering);
  t.wifi_cluster_management_s = module_s(kWifiClusterManagement);
  t.wifi_overhead_s = t.wifi_clustering_s + t.wifi_cluster_management_s;
  t.optimisation_s = module_s("optimisation");
  t.total_s = module_s("total");
  return t;
}

}  // namespace wifislam::eval
