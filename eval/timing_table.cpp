#include "eval/timing_table.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/run_format.hpp"

namespace wifislam::eval {

namespace module = run_folder::module;
namespace key = run_folder::timing_key;
namespace role_key = run_folder::role_key;

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
  j["roles"] = nlohmann::ordered_json::object();
  for (const auto& [name, r] : roles) {
    j["roles"][name] = {{role_key::kComparisons, r.comparisons},
                        {role_key::kRansacRuns, r.ransac_runs},
                        {role_key::kVerified, r.verified},
                        {role_key::kAccepted, r.accepted},
                        {role_key::kTimeS, r.time_s}};
  }
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
  auto number = [&](const nlohmann::json& v, const std::string& where) {
    if (!v.is_number()) throw ParseError(file, where, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < 0) throw ParseError(file, where, "expected a finite value >= 0");
    return x;
  };
  if (!j.is_object()) throw ParseError(file, "", "expected a JSON object");
  TimingTable t;
  if (j.contains(key::kModules)) {
    if (!j[key::kModules].is_object()) throw ParseError(file, key::kModules, "expected an object");
    for (const auto& [name, m] : j[key::kModules].items()) {
      const std::string where = std::string(key::kModules) + "." + name;
      if (!m.is_object() || !m.contains("total_s")) {
        throw ParseError(file, where, "expected {\"total_s\": ..., \"calls\": ...}");
      }
      ModuleTiming mt;
      mt.total_s = number(m["total_s"], where + ".total_s");
      if (m.contains("calls")) {
        mt.calls = static_cast<std::int64_t>(number(m["calls"], where + ".calls"));
      }
      t.modules[name] = mt;
    }
  }
  if (j.contains(key::kCounters)) {
    if (!j[key::kCounters].is_object()) {
      throw ParseError(file, key::kCounters, "expected an object");
    }
    for (const auto& [name, v] : j[key::kCounters].items()) {
      t.counters[name] =
          static_cast<std::int64_t>(number(v, std::string(key::kCounters) + "." + name));
    }
  }
  if (j.contains(key::kRoles)) {
    if (!j[key::kRoles].is_object()) throw ParseError(file, key::kRoles, "expected an object");
    for (const auto& [name, role] : j[key::kRoles].items()) {
      const std::string where = std::string(key::kRoles) + "." + name;
      if (!role.is_object()) throw ParseError(file, where, "expected an object");
      // Clang before 16 cannot capture a structured binding in a lambda (the fuzz preset's).
      const auto& r = role;
      auto field = [&](const char* k) {
        if (!r.contains(k)) throw ParseError(file, where + "." + k, "missing");
        return number(r[k], where + "." + k);
      };
      RoleTiming rt;
      rt.comparisons = static_cast<std::int64_t>(field(role_key::kComparisons));
      rt.ransac_runs = static_cast<std::int64_t>(field(role_key::kRansacRuns));
      rt.verified = static_cast<std::int64_t>(field(role_key::kVerified));
      rt.accepted = static_cast<std::int64_t>(field(role_key::kAccepted));
      rt.time_s = field(role_key::kTimeS);
      t.roles[name] = rt;
    }
  }
  if (j.contains(key::kWallS)) t.wall_s = number(j[key::kWallS], key::kWallS);
  auto module_s = [&](const char* name) {
    const auto it = t.modules.find(name);
    return it == t.modules.end() ? 0.0 : it->second.total_s;
  };
  t.loop_closure_detection_s = module_s(module::kLoopClosureDetection);
  t.candidate_selection_s = module_s(module::kCandidateSelection);
  t.wifi_clustering_s = module_s(module::kWifiClustering);
  t.wifi_cluster_management_s = module_s(module::kWifiClusterManagement);
  t.wifi_overhead_s = t.wifi_clustering_s + t.wifi_cluster_management_s;
  t.optimisation_s = module_s(module::kOptimisation);
  t.total_s = module_s(module::kTotal);
  return t;
}

}  // namespace wifislam::eval
