#include "slam/io/run_folder_writer.hpp"

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/run_format.hpp"
#include "core/tum_trajectory.hpp"

namespace wifislam::slam::io {

namespace {

nlohmann::json pose_json(const Pose& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d& t = pose.translation();
  return {{"t", {t.x(), t.y(), t.z()}}, {"q_xyzw", {q.x(), q.y(), q.z(), q.w()}}};
}

}  // namespace

nlohmann::json graph_to_json(const graph::PoseGraph& graph) {
  nlohmann::json nodes = nlohmann::json::array();
  for (const graph::GraphNode& n : graph.nodes()) {
    nodes.push_back({{"id", n.id},
                     {"frame_index", n.frame_index},
                     {"time", n.time.to_string(9)},
                     {"pose", pose_json(n.pose)}});
  }
  nlohmann::json edges = nlohmann::json::array();
  for (const graph::GraphEdge& e : graph.edges()) {
    std::vector<double> info(e.information.data(), e.information.data() + 36);
    edges.push_back({{"from", e.from},
                     {"to", e.to},
                     {"type", to_string(e.type)},
                     {"inliers", e.inliers},
                     {"from_to", pose_json(e.from_to)},
                     {"information", info},
                     {run_folder::graph_key::kPruned, e.pruned},
                     {run_folder::graph_key::kWeight, e.weight}});
  }
  return {{"pose_convention", "camera-to-map; edge from_to = pose of 'to' in the frame of 'from'"},
          {"information_convention",
           "6x6 column-major, residual [translation; rotation] of from_to in frame 'from'"},
          {"nodes", std::move(nodes)},
          {"edges", std::move(edges)}};
}

std::string loop_closures_csv(const system::SlamSystem& system) {
  std::string out = run_folder::csv_header(run_folder::loop_closures_column::kAll);
  const graph::PoseGraph& graph = system.graph();
  for (const system::LoopClosureRecord& l : system.loop_closures()) {
    const graph::GraphNode& a = graph.node(l.from);
    const graph::GraphNode& b = graph.node(l.to);
    const Eigen::Quaterniond q(l.from_to.linear());
    const Eigen::Vector3d& t = l.from_to.translation();
    out += fmt::format("{},{},{},{},{},{},{},{},{:.4f},{},{},{},{},{},{},{}\n", l.from, l.to,
                       a.frame_index, b.frame_index, a.time.to_string(6), b.time.to_string(6),
                       to_string(l.role), l.inliers, l.rms_reprojection_px, t.x(), t.y(), t.z(),
                       q.x(), q.y(), q.z(), q.w());
  }
  return out;
}

void write_run_folder(const std::filesystem::path& run_dir, const system::SlamSystem& system,
                      const system::RunSummary& summary, bool overwrite,
                      const nlohmann::json& extra_run_info) {
  AtomicDirectory dir(run_dir, overwrite);
  const std::filesystem::path& out = dir.staging_path();
  write_tum_trajectory(
      (out / run_folder::kTrajectory).string(), system.trajectory(),
      {"camera-to-map pose of every frame (wifislam slam, " + summary.label() + ")",
       "timestamp tx ty tz qx qy qz qw"});
  write_tum_trajectory((out / run_folder::kKeyframes).string(), system.keyframe_trajectory(),
                       {"camera-to-map pose of every keyframe; line k = keyframe id k",
                        "timestamp tx ty tz qx qy qz qw"});
  write_file_atomic(out / run_folder::kGraph, graph_to_json(system.graph()).dump(1) + "\n");
  write_file_atomic(out / run_folder::kLoopClosures, loop_closures_csv(system));
  nlohmann::json timing = system.instrumentation().to_json();
  timing[run_folder::timing_key::kWallS] = summary.wall_s;
  write_file_atomic(out / run_folder::kTiming, timing.dump(1) + "\n");
  nlohmann::json run = {{run_folder::run_key::kFormat, run_folder::kFormatName},
                        {run_folder::run_key::kFormatVersion, run_folder::kFormatVersion}};
  run.update(summary.to_json());
  run["options"] = to_json(system.options());
  run["frontend_summary"] = system.front_end().summary();
  run["edge_acceptance"] = system.front_end().acceptance().name();
  nlohmann::json pruning = nlohmann::json::array();
  for (const optimize::PruningStage& stage : system.pruning()) {
    pruning.push_back({{"threshold_chi2", stage.threshold_chi2},
                       {"pruned", stage.pruned},
                       {"discounted", stage.discounted},
                       {"reoptimised", stage.optimisation.ran},
                       {"usable", stage.optimisation.usable}});
  }
  run[run_folder::run_key::kPruning] = std::move(pruning);
  run["final_optimisation"] = {{"usable", system.final_optimisation().usable},
                               {"iterations", system.final_optimisation().iterations},
                               {"termination", system.final_optimisation().termination}};
  run["stream"] = {{"has_wifi", system.stream_info().has_wifi},
                   {"has_odometry", system.stream_info().has_odometry},
                   {"intrinsics",
                    {{"width_px", system.stream_info().intrinsics.width_px},
                     {"height_px", system.stream_info().intrinsics.height_px},
                     {"fx_px", system.stream_info().intrinsics.fx_px},
                     {"fy_px", system.stream_info().intrinsics.fy_px},
                     {"cx_px", system.stream_info().intrinsics.cx_px},
                     {"cy_px", system.stream_info().intrinsics.cy_px}}}};
  run.update(extra_run_info);
  write_file_atomic(out / run_folder::kRun, run.dump(1) + "\n");
  system.front_end().write_outputs(out);
  dir.commit();
}

}  // namespace wifislam::slam::io
