#pragma once
// A hand-built dataset and run folder in the aliasing_ladder scene (every wing looks the same),
// for scoring loop closures against exact ground truth. The camera walks north through rung 0
// (segment "A"), round the ladder, north through rung 2 ("aliased": looks exactly like A, 20 m
// away), back round to rung 0 and north through it again ("revisit": a true revisit of A, about
// 90 m later). Keyframes every metre of travel; their depth images are rendered by OSMesa from
// the generated world (ideal depth cut at the Kinect's 4 m). The run's trajectory and keyframes
// are the ground truth moved by a fixed rigid transform (a perfect estimate in its own map
// frame); loop_closures.csv is written by each test.

#include <filesystem>
#include <string>
#include <vector>

#include "core/pose.hpp"
#include "core/timestamp.hpp"

namespace wifislam::test {

struct LadderRun {
  std::filesystem::path dataset_dir, run_dir;
  std::vector<Pose> keyframe_poses;  // ground truth
  std::vector<Timestamp> keyframe_times;
  std::vector<std::string> keyframe_segment;  // "A", "aliased", "revisit" or "transit"

  /// The keyframe of `segment` whose ground-truth y is nearest to `y_m`.
  int keyframe_near(const std::string& segment, double y_m) const;
  /// Ground-truth pose of `to` in the camera frame of `from`.
  Pose true_relative(int from, int to) const;
};

struct LoopClosureRow {
  int from = 0, to = 0;
  Pose from_to = Pose::Identity();  // the "estimated" relative pose
};

/// An accepted edge of the run's graph.json.
struct GraphEdgeRow {
  int from = 0, to = 0;
  const char* type = "loop";
  Pose from_to = Pose::Identity();  // the "estimated" relative pose
  int pruned = -1;                  // -1: no "pruned" key (format before 3), 0/1: false/true
};

/// Builds both folders under `root` (replaced). `depth` false: no depth images (like a dataset
/// generated with --no-images).
LadderRun build_ladder_run(const std::filesystem::path& root, bool depth);

/// Writes the run's loop_closures.csv.
void write_loop_closures(const LadderRun& run, const std::vector<LoopClosureRow>& rows);

/// Writes the run's graph.json: an odometry edge between consecutive keyframes (their true
/// relative pose) followed by `edges`.
void write_graph(const LadderRun& run, const std::vector<GraphEdgeRow>& edges);

}  // namespace wifislam::test
