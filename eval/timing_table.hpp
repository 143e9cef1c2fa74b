#pragma once
// The time table of a run, from its timing.json (layout in core/run_format.hpp): the paper's
// loop-closure detection
// time, Wi-Fi overhead (clustering + cluster management; 0 for a run without Wi-Fi) and
// optimisation time, with the deterministic work counters beside them (wall-clock depends on the
// machine, counters do not).

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace wifislam::eval {

struct ModuleTiming {
  double total_s = 0.0;
  std::int64_t calls = 0;
};

/// One candidate role's work (core/run_format.hpp, "roles").
struct RoleTiming {
  std::int64_t comparisons = 0, ransac_runs = 0, verified = 0, accepted = 0;
  double time_s = 0.0;
};

struct TimingTable {
  double loop_closure_detection_s = 0.0;
  double candidate_selection_s = 0.0;
  double wifi_clustering_s = 0.0;
  double wifi_cluster_management_s = 0.0;
  double wifi_overhead_s = 0.0;  // clustering + cluster management
  double optimisation_s = 0.0;
  double total_s = 0.0;  // the pipeline's own "total" module
  double wall_s = 0.0;   // the whole run, reading input included
  std::map<std::string, ModuleTiming> modules;
  std::map<std::string, std::int64_t> counters;
  /// Per candidate role ("predecessor", "neighbour", "long_term", "relocalisation", "tracking",
  /// and the roles of other front ends); empty for runs written before format version 2.
  std::map<std::string, RoleTiming> roles;

  std::int64_t counter(const std::string& name) const {
    const auto it = counters.find(name);
    return it == counters.end() ? 0 : it->second;
  }
  nlohmann::ordered_json to_json() const;
};

/// Throws IoError (unreadable) or ParseError naming the file (and line/column for bad JSON, the
/// key for a wrong type or a negative time).
TimingTable read_timing_json(const std::filesystem::path& path);

}  // namespace wifislam::eval
