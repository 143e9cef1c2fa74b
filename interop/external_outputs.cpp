#include "interop/external_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/contained_file.hpp"
#include "core/error.hpp"
#include "core/line_cursor.hpp"
#include "core/run_format.hpp"
#include "core/text_lines.hpp"
#include "core/tum_trajectory.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

/// A closure stamp is its keyframe's when they differ by less than this (TUM's association bound).
constexpr std::int64_t kStampToleranceNs = 20'000'000;

/// A declared output, checked before anything reads it: a regular file below the system's
/// folder with no symbolic link on its way (core/contained_file.hpp), so that a link to
/// /etc/passwd or to the dataset's ground truth is refused, never imported.
fs::path required_output(const fs::path& system_out, const std::string& name, const char* what) {
  const fs::path p = system_out / name;
  const ContainedFile file = inspect_file_below(system_out, name);
  if (file.state == ContainedFile::State::kMissing) {
    throw ParseError(p.string(), "",
                     fmt::format("the system wrote no {} (outputs: {})", what, name));
  }
  if (file.state == ContainedFile::State::kRefused) throw ParseError(p.string(), "", file.problem);
  return p;
}

/// The largest graph.json read (nlohmann's parse takes about ten times a file's size).
constexpr std::uintmax_t kMaxGraphBytes = std::uintmax_t{256} << 20;

/// graph.json as the run format has it (core/run_format.hpp's graph_key): an object with the
/// arrays "nodes" and "edges", each edge an object with integer "from" and "to". eval checks the
/// rest when it scores the run.
void check_graph(const fs::path& file) {
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec || bytes > kMaxGraphBytes) {
    throw ParseError(file.string(), "", fmt::format("larger than {} MiB", kMaxGraphBytes >> 20));
  }
  std::ifstream in(file, std::ios::binary);
  const nlohmann::json graph = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!graph.is_object()) throw ParseError(file.string(), "", "expected a JSON object");
  for (const char* key : {run_folder::graph_key::kNodes, run_folder::graph_key::kEdges}) {
    if (!graph.contains(key) || !graph[key].is_array()) {
      throw ParseError(file.string(), key, "expected an array");
    }
  }
  std::size_t i = 0;
  for (const auto& edge : graph[run_folder::graph_key::kEdges]) {
    for (const char* key : {run_folder::graph_key::kFrom, run_folder::graph_key::kTo}) {
      if (!edge.is_object() || !edge.contains(key) || !edge[key].is_number_integer()) {
        throw ParseError(file.string(), fmt::format("edges[{}].{}", i, key),
                         "expected a keyframe id");
      }
    }
    ++i;
  }
}

/// wifi_clusters.csv as the run format has it: a text file whose header starts with cluster_id.
void check_wifi_clusters(const fs::path& file) {
  LineCursor cursor(file.string());  // its first line that is not blank or a comment
  TextLine line;
  if (!cursor.next(line)) {
    throw ParseError(file.string(), "", "no header: expected wifislam's wifi_clusters.csv");
  }
  if (line.text.rfind("cluster_id,", 0) != 0) {
    throw ParseError(cursor.where(line.number), "",
                     "expected the header of wifislam's wifi_clusters.csv (cluster_id,...)");
  }
}

/// The keyframe whose stamp is nearest `t`, within the tolerance.
std::optional<std::size_t> keyframe_at(const Trajectory& keyframes, Timestamp t) {
  const auto it = std::lower_bound(keyframes.begin(), keyframes.end(), t,
                                   [](const StampedPose& p, Timestamp x) { return p.time < x; });
  std::optional<std::size_t> best;
  std::int64_t best_ns = kStampToleranceNs;
  for (auto c = it == keyframes.begin() ? it : it - 1; c != keyframes.end() && c <= it; ++c) {
    const std::int64_t d = std::abs(c->time.ns - t.ns);
    if (d < best_ns) best_ns = d, best = static_cast<std::size_t>(c - keyframes.begin());
  }
  return best;
}

/// The system's loop closures in our loop_closures.csv columns (see the header).
std::string convert_loop_closures(const fs::path& file, const Trajectory& keyframes,
                                  const Trajectory& trajectory) {
  std::map<std::string, std::size_t> column;
  std::string out = run_folder::csv_header(run_folder::loop_closures_column::kAll);
  bool header = true;
  for_each_text_line(file.string(), [&](const TextLine& line) {
    if (line.text.empty() || line.text.front() == '#') return;
    const std::vector<std::string_view> fields = split_fields(line.text, ',');
    const std::string where = fmt::format("{}:{}", file.string(), line.number);
    if (header) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (!column.emplace(std::string(fields[i]), i).second) {
          throw ParseError(where, std::string(fields[i]), "column named twice in the header");
        }
      }
      for (const char* needed : {"from_time", "to_time"}) {
        if (!column.count(needed)) throw ParseError(where, needed, "missing column");
      }
      header = false;
      return;
    }
    if (fields.size() != column.size()) {
      throw ParseError(where, "",
                       fmt::format("{} fields, the header has {}", fields.size(), column.size()));
    }
    const auto field = [&](const char* name) -> std::optional<std::string_view> {
      const auto c = column.find(name);
      return c == column.end() ? std::nullopt : std::optional(fields[c->second]);
    };
    std::size_t index[2] = {0, 0}, frame[2] = {0, 0};
    for (int end = 0; end < 2; ++end) {
      const char* name = end == 0 ? "from_time" : "to_time";
      const std::optional<Timestamp> t = Timestamp::parse(*field(name));
      if (!t) throw ParseError(where, name, "'" + std::string(*field(name)) + "' is not a time");
      const std::optional<std::size_t> k = keyframe_at(keyframes, *t);
      if (!k) {
        throw ParseError(where, name,
                         fmt::format("no keyframe (or trajectory pose) within 0.02 s of {}",
                                     t->to_tum_string()));
      }
      index[end] = *k;
      // The frame index counts trajectory poses (keyframes may be a subset of them).
      frame[end] = keyframe_at(trajectory, *t).value_or(*k);
    }
    const StampedPose& from = keyframes[index[0]];
    const StampedPose& to = keyframes[index[1]];
    Pose from_to = from.pose().inverse() * to.pose();
    if (field("qw")) {
      double v[7];
      const char* names[7] = {"tx", "ty", "tz", "qx", "qy", "qz", "qw"};
      for (int i = 0; i < 7; ++i) {
        const auto text = field(names[i]);
        if (!text || !parse_double(*text, v[i]) || !std::isfinite(v[i])) {
          throw ParseError(where, names[i], "expected a finite number");
        }
      }
      const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
      if (q.norm() < 1e-9) throw ParseError(where, "qw", "zero quaternion");
      from_to = pose_from_translation_quaternion(Eigen::Vector3d(v[0], v[1], v[2]), q);
    }
    long long inliers = 0;
    if (const auto text = field("inliers"); text && !parse_int64(*text, inliers)) {
      throw ParseError(where, "inliers", "expected an integer");
    }
    const std::string role = field("role") ? std::string(*field("role")) : "external";
    const Eigen::Quaterniond q(from_to.linear());
    const Eigen::Vector3d& t = from_to.translation();
    out += fmt::format("{},{},{},{},{},{},{},{},0,{},{},{},{},{},{},{}\n", index[0], index[1],
                       frame[0], frame[1], from.time.to_tum_string(), to.time.to_tum_string(), role,
                       inliers, t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  });
  return out;
}

/// timing.json from the system's time log (seconds by module) and the measured run.
std::string timing_json(const fs::path& time_log, double cpu_s, double wall_s) {
  nlohmann::json modules = {{run_folder::module::kTotal, {{"total_s", cpu_s}, {"calls", 1}}}};
  if (!time_log.empty()) {
    std::ifstream in(time_log);
    const nlohmann::json log = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!log.is_object()) throw ParseError(time_log.string(), "", "expected a JSON object");
    for (const char* module :
         {run_folder::module::kLoopClosureDetection, run_folder::module::kOptimisation}) {
      const std::string key = std::string(module) + "_s";
      if (!log.contains(key)) continue;
      if (!log[key].is_number() || !(log[key].get<double>() >= 0)) {
        throw ParseError(time_log.string(), key, "expected seconds >= 0");
      }
      modules[module] = {{"total_s", log[key].get<double>()}, {"calls", 1}};
    }
  }
  return nlohmann::json{{run_folder::timing_key::kModules, modules},
                        {run_folder::timing_key::kWallS, wall_s}}
             .dump(1) +
         "\n";
}

}  // namespace

ImportedOutputs import_external_outputs(const ExternalSystem& system, const fs::path& system_out,
                                        const fs::path& run_dir, bool wifi, double cpu_s,
                                        double wall_s) {
  // Every declared output is read and checked first; nothing is written before all passed.
  ImportedOutputs imported;
  const Trajectory trajectory =
      read_tum_trajectory(required_output(system_out, system.trajectory, "trajectory").string());
  if (trajectory.empty()) {
    throw ParseError((system_out / system.trajectory).string(), "", "the trajectory is empty");
  }
  imported.frames = static_cast<std::int64_t>(trajectory.size());
  Trajectory keyframes;
  if (!system.keyframes.empty()) {
    keyframes =
        read_tum_trajectory(required_output(system_out, system.keyframes, "keyframes").string());
  } else if (!system.loop_closures.empty() && system.graph.empty()) {
    keyframes = trajectory;  // every pose a keyframe: the closures' stamps index into it
  }
  imported.keyframes = static_cast<std::int64_t>(keyframes.size());
  std::string closures;
  if (!system.loop_closures.empty()) {
    closures = convert_loop_closures(
        required_output(system_out, system.loop_closures, "loop closures"), keyframes, trajectory);
    imported.loop_closures = std::count(closures.begin(), closures.end(), '\n') - 1;
  }
  fs::path graph, clusters;
  if (!system.graph.empty()) {
    graph = required_output(system_out, system.graph, "graph");
    check_graph(graph);
  }
  if (wifi && !system.wifi_clusters.empty()) {
    clusters = required_output(system_out, system.wifi_clusters, "Wi-Fi clusters");
    check_wifi_clusters(clusters);
  }
  const fs::path time_log = system.time_log.empty()
                                ? fs::path()
                                : required_output(system_out, system.time_log, "time log");
  const std::string timing = timing_json(time_log, cpu_s, wall_s);

  write_tum_trajectory((run_dir / run_folder::kTrajectory).string(), trajectory,
                       {"camera-to-map pose of every frame (external system " + system.name + ")",
                        "timestamp tx ty tz qx qy qz qw"});
  if (!keyframes.empty()) {
    write_tum_trajectory(
        (run_dir / run_folder::kKeyframes).string(), keyframes,
        {"keyframes of external system " + system.name, "timestamp tx ty tz qx qy qz qw"});
  }
  if (!system.loop_closures.empty())
    write_file_atomic(run_dir / run_folder::kLoopClosures, closures);
  if (!graph.empty()) {
    fs::copy_file(graph, run_dir / run_folder::kGraph);
    imported.graph = true;
  }
  if (!clusters.empty()) fs::copy_file(clusters, run_dir / run_folder::kWifiClusters);
  write_file_atomic(run_dir / run_folder::kTiming, timing);
  return imported;
}

}  // namespace wifislam::interop
