#pragma once
// Where the time goes: wall-clock per module and deterministic work counters (docs/evaluation.md:
// time is reported both ways, because wall-clock depends on the
// machine and the counters do not). Written to timing.json.

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/run_format.hpp"

namespace wifislam::slam {

/// Module and counter names live with the run-folder format (core/run_format.hpp), which eval
/// reads too; these aliases, for every slam library, keep the pipeline's call sites short.
namespace module = ::wifislam::run_folder::module;
namespace counter = ::wifislam::run_folder::counter;

}  // namespace wifislam::slam

namespace wifislam::slam::util {

class Instrumentation {
 public:
  struct ModuleTime {
    double total_s = 0.0;
    std::int64_t calls = 0;
  };

  /// Adds `seconds` of wall-clock to `module`, as one call.
  void add_time(const std::string& module, double seconds);
  /// Adds `seconds` to `module` within a call already counted (time spent elsewhere on its
  /// behalf: slam/feature/feature_store.hpp).
  void add_seconds(const std::string& module, double seconds);
  void count(const std::string& name, std::int64_t amount = 1);

  /// Work of one visual comparison made for `role` (a candidate role, or "tracking"): its RANSAC
  /// runs, whether it passed verification, and its wall-clock.
  void record_comparison(const std::string& role, std::int64_t ransac_runs, bool verified,
                         double seconds);
  /// A verified comparison of `role` became a graph edge.
  void record_role_accepted(const std::string& role);

  /// Loop-closure detection time of one keyframe, with the map size it searched (benchmark of
  /// how detection time grows with the map).
  void record_keyframe_search(std::int64_t map_keyframes, std::int64_t comparisons, double seconds);

  double seconds(const std::string& module) const;
  std::int64_t counter(const std::string& name) const;
  const std::map<std::string, ModuleTime>& modules() const { return modules_; }
  const std::map<std::string, std::int64_t>& counters() const { return counters_; }

  struct KeyframeSearch {
    std::int64_t map_keyframes = 0, comparisons = 0;
    double seconds = 0.0;
  };
  const std::vector<KeyframeSearch>& keyframe_searches() const { return keyframe_searches_; }

  struct RoleWork {
    std::int64_t comparisons = 0, ransac_runs = 0, verified = 0, accepted = 0;
    double time_s = 0.0;
  };
  const std::map<std::string, RoleWork>& roles() const { return roles_; }

  /// {"modules": {name: {"total_s", "calls"}}, "counters": {...}, "roles": {role: {...}},
  /// "keyframe_searches": [...]} (core/run_format.hpp).
  nlohmann::json to_json() const;

 private:
  std::map<std::string, ModuleTime> modules_;
  std::map<std::string, std::int64_t> counters_;
  std::vector<KeyframeSearch> keyframe_searches_;
  std::map<std::string, RoleWork> roles_;
};

/// Adds the wall-clock between construction and destruction (or stop()) to a module.
class ScopedTimer {
 public:
  ScopedTimer(Instrumentation& instrumentation, std::string module)
      : instrumentation_(&instrumentation),
        module_(std::move(module)),
        start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { stop(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

  /// Stops the clock and returns the elapsed seconds (0 after the first call).
  double stop();

 private:
  Instrumentation* instrumentation_;
  std::string module_;
  std::chrono::steady_clock::time_point start_;
  bool stopped_ = false;
};

}  // namespace wifislam::slam::util
