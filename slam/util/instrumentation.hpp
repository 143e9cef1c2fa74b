#pragma once
// Where the time goes: wall-clock per module and deterministic work counters (DESIGN.md,
// "Ground truth and metrics": time is reported both ways, because wall-clock depends on the
// machine and the counters do not). Written to timing.json.

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wifislam::slam {

/// Module names used by the pipeline (others, e.g. the Wi-Fi module's, may add their own).
namespace module {
inline constexpr const char* kFeatureExtraction = "feature_extraction";
inline constexpr const char* kMatching = "matching";
inline constexpr const char* kRansac = "ransac";
inline constexpr const char* kCandidateSelection = "candidate_selection";
inline constexpr const char* kLoopClosureDetection = "loop_closure_detection";
inline constexpr const char* kOptimisation = "optimisation";
inline constexpr const char* kTotal = "total";
}  // namespace module

/// Counter names used by the pipeline.
namespace counter {
inline constexpr const char* kFrames = "frames";
inline constexpr const char* kKeyframes = "keyframes";
inline constexpr const char* kCandidateComparisons = "candidate_comparisons";
inline constexpr const char* kRansacRuns = "ransac_runs";
inline constexpr const char* kAcceptedTransformations = "accepted_transformations";
inline constexpr const char* kLoopClosures = "loop_closures";
inline constexpr const char* kOptimisations = "optimisations";
inline constexpr const char* kTrackingFailures = "tracking_failures";
}  // namespace counter

class Instrumentation {
 public:
  struct ModuleTime {
    double total_s = 0.0;
    std::int64_t calls = 0;
  };

  /// Adds `seconds` of wall-clock to `module`.
  void add_time(const std::string& module, double seconds);
  void count(const std::string& name, std::int64_t amount = 1);

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

  /// {"modules": {name: {"total_s", "calls"}}, "counters": {...}, "keyframe_searches": [...]}.
  nlohmann::json to_json() const;

 private:
  std::map<std::string, ModuleTime> modules_;
  std::map<std::string, std::int64_t> counters_;
  std::vector<KeyframeSearch> keyframe_searches_;
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

}  // namespace wifislam::slam
