#include "slam/util/instrumentation.hpp"
#include "core/wall_clock.hpp"

#include <nlohmann/json.hpp>

namespace wifislam::slam::util {

void Instrumentation::add_time(const std::string& module, double seconds) {
  ModuleTime& m = modules_[module];
  m.total_s += seconds;
  ++m.calls;
}

void Instrumentation::add_seconds(const std::string& module, double seconds) {
  modules_[module].total_s += seconds;
}

void Instrumentation::count(const std::string& name, std::int64_t amount) {
  counters_[name] += amount;
}

void Instrumentation::record_keyframe_search(std::int64_t map_keyframes, std::int64_t comparisons,
                                             double seconds) {
  keyframe_searches_.push_back({map_keyframes, comparisons, seconds});
}

void Instrumentation::record_comparison(const std::string& role, std::int64_t ransac_runs,
                                        bool verified, double seconds) {
  RoleWork& r = roles_[role];
  ++r.comparisons;
  r.ransac_runs += ransac_runs;
  if (verified) ++r.verified;
  r.time_s += seconds;
}

void Instrumentation::record_role_accepted(const std::string& role) { ++roles_[role].accepted; }

double Instrumentation::seconds(const std::string& module) const {
  const auto it = modules_.find(module);
  return it == modules_.end() ? 0.0 : it->second.total_s;
}

std::int64_t Instrumentation::counter(const std::string& name) const {
  const auto it = counters_.find(name);
  return it == counters_.end() ? 0 : it->second;
}

nlohmann::json Instrumentation::to_json() const {
  namespace key = run_folder::timing_key;
  namespace role_key = run_folder::role_key;
  nlohmann::json out;
  out[key::kModules] = nlohmann::json::object();
  for (const auto& [name, m] : modules_) {
    out[key::kModules][name] = {{"total_s", m.total_s}, {"calls", m.calls}};
  }
  out[key::kCounters] = nlohmann::json::object();
  for (const auto& [name, value] : counters_) out[key::kCounters][name] = value;
  out[key::kRoles] = nlohmann::json::object();
  for (const auto& [name, r] : roles_) {
    out[key::kRoles][name] = {{role_key::kComparisons, r.comparisons},
                              {role_key::kRansacRuns, r.ransac_runs},
                              {role_key::kVerified, r.verified},
                              {role_key::kAccepted, r.accepted},
                              {role_key::kTimeS, r.time_s}};
  }
  nlohmann::json searches = nlohmann::json::array();
  for (const KeyframeSearch& s : keyframe_searches_) {
    searches.push_back({{"map_keyframes", s.map_keyframes},
                        {"comparisons", s.comparisons},
                        {"seconds", s.seconds}});
  }
  out[key::kKeyframeSearches] = std::move(searches);
  return out;
}

double ScopedTimer::stop() {
  if (stopped_) return 0.0;
  stopped_ = true;
  const double s = seconds_since(start_);
  instrumentation_->add_time(module_, s);
  return s;
}

}  // namespace wifislam::slam::util
