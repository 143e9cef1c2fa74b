#pragma once
// The edges of a run folder's graph.json (format in core/run_format.hpp): every accepted edge
// with its type, estimated relative pose and whether the after-run pruning removed it. Nodes are
// not read: keyframes.txt already gives the keyframes (line k = keyframe id k).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/pose.hpp"

namespace wifislam::eval {

struct GraphEdgeRecord {
  std::int64_t from_keyframe = -1, to_keyframe = -1;
  std::string type;  // run_folder::edge_type: odometry, visual, loop, weak (others kept as read)
  std::int64_t inliers = 0;
  Pose from_to = Pose::Identity();  // estimated pose of `to` in the camera frame of `from`
  bool pruned = false;              // absent before run format version 3
  double weight = 1.0;              // absent before run format version 3
  std::size_t index = 0;            // position in "edges", for messages
};

/// Throws IoError (unreadable) or ParseError(file, "edges[i].key", ...) for invalid JSON, a
/// missing or wrongly typed key, a negative keyframe id, a non-finite number, a zero
/// quaternion or a negative weight.
std::vector<GraphEdgeRecord> read_graph_edges_json(const std::filesystem::path& path);

}  // namespace wifislam::eval
