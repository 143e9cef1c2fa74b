#include "slam/util/instrumentation.hpp"

namespace wifislam::slam {

void Instrumentation::add_time(const std::string& module, double seconds) {
  ModuleTime& m = modules_[module];
  m.total_s += seconds;
  ++m.calls;
}

void Instrumentation::count(const std::string& name, std::int64_t amount) {
  counters_[name] += amount;
}

void Instrumentation::record_keyframe_search(std::int64_t map_keyframes, std::int64_t comparisons,
                                             double seconds) {
  keyframe_searches_.push_back({map_keyframes, comparisons, seconds});
}

double Instrumentation::seconds(const std::string& module) const {
  const auto it = modules_.find(module);
  return it == modules_.end() ? 0.0 : it->second.total_s;
}

std::int64_t Instrumentation::counter(const std::string& name) const {
  const auto it = counters_.find(name);
  return it == counters_.end() ? 0 : it->second;
}

nlohmann::json Instrumentation::to_json() const {
  nlohmann::json out;
  out["modules"] = nlohmann::json::object();
  for (const auto& [name, m] : modules_) {
    out["modules"][name] = {{"total_s", m.total_s}, {"calls", m.calls}};
  }
  out["counters"] = nlohmann::json::object();
  for (const auto& [name, value] : counters_) out["counters"][name] = value;
  nlohmann::json searches = nlohmann::json::array();
  for (const KeyframeSearch& s : keyframe_searches_) {
    searches.push_back({{"map_keyframes", s.map_keyframes},
                        {"comparisons", s.comparisons},
                        {"seconds", s.seconds}});
  }
  out["keyframe_searches"] = std::move(searches);
  return out;
}

double ScopedTimer::stop() {
  if (stopped_) return 0.0;
  stopped_ = true;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  instrumentation_->add_time(module_, s);
  return s;
}

}  // namespace wifislam::slam
