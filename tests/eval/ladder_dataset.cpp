#include "tests/eval/ladder_dataset.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/dataset_calibration.hpp"
#include "core/tum_trajectory.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::test {

namespace fs = std::filesystem;

namespace {

constexpr double kCameraHeightM = 1.2;
constexpr double kStepM = 0.1;           // ground-truth sample spacing (1 m/s at 10 Hz)
constexpr double kTurnStepRad = 0.1745;  // about 10 deg per sample when turning in place
constexpr double kKeyframeSpacingM = 1.0;
constexpr double kSensorMaxRangeM = 4.0;  // Kinect v1

struct Leg {
  Eigen::Vector2d to;
  const char* segment;
};

CameraIntrinsics small_intrinsics() {
  CameraIntrinsics k;
  k.width_px = 320;
  k.height_px = 240;
  k.fx_px = k.fy_px = 262.5;
  k.cx_px = 159.5;
  k.cy_px = 119.5;
  return k;
}

/// Where the estimate's map frame is (any fixed rigid transform: ATE must undo it).
Pose map_from_world() {
  Pose t = Pose::Identity();
  t.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(-3.0, 5.0, 0.2);
  return t;
}

}  // namespace

int LadderRun::keyframe_near(const std::string& segment, double y_m) const {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < keyframe_poses.size(); ++k) {
    if (keyframe_segment[k] != segment) continue;
    const double d = std::abs(keyframe_poses[k].translation().y() - y_m);
    if (d < best_d) best_d = d, best = static_cast<int>(k);
  }
  return best;
}

Pose LadderRun::true_relative(int from, int to) const {
  return keyframe_poses[static_cast<std::size_t>(from)].inverse() *
         keyframe_poses[static_cast<std::size_t>(to)];
}

namespace {

/// Dense ground truth along the ladder's legs: straight legs at kStepM, turns in place at
/// kTurnStepRad; `segment` receives each sample's leg name.
Trajectory ladder_ground_truth(std::vector<std::string>& sample_segment) {
  const std::vector<Leg> legs = {
      {{0, 9.5}, "A"},        {{0, 12}, "transit"},    {{10, 12}, "transit"},
      {{10, 0}, "transit"},   {{20, 0}, "transit"},    {{20, 1.5}, "transit"},
      {{20, 9.5}, "aliased"}, {{20, 12}, "transit"},   {{0, 12}, "transit"},
      {{0, 0}, "transit"},    {{0.2, 1.8}, "revisit"}, {{0.2, 9.8}, "revisit"}};

  Trajectory ground_truth;
  Eigen::Vector2d p(0, 1.5);
  double yaw = std::numbers::pi / 2;
  std::int64_t tick = 0;
  auto emit = [&](const char* segment) {
    ground_truth.push_back(
        StampedPose::from_pose(Timestamp::from_ns(1'000'000'000LL + tick++ * 100'000'000LL),
                               camera_pose_from_planar(p.x(), p.y(), yaw, kCameraHeightM)));
    sample_segment.emplace_back(segment);
  };
  emit("A");
  for (const Leg& leg : legs) {
    const Eigen::Vector2d d = leg.to - p;
    const double target = std::atan2(d.y(), d.x());
    double turn = std::remainder(target - yaw, 2 * std::numbers::pi);
    while (std::abs(turn) > 1e-9) {
      const double step = std::clamp(turn, -kTurnStepRad, kTurnStepRad);
      yaw += step;
      turn -= step;
      emit("transit");
    }
    const Eigen::Vector2d start = p;
    const int steps = static_cast<int>(std::ceil(d.norm() / kStepM - 1e-9));
    for (int s = 1; s <= steps; ++s) {
      p = start + d * (static_cast<double>(s) / steps);
      emit(leg.segment);
    }
  }
  return ground_truth;
}

/// Keyframes every metre of travel.
void pick_keyframes(const Trajectory& ground_truth, const std::vector<std::string>& sample_segment,
                    LadderRun& run) {
  double since_m = 0;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    if (i > 0)
      since_m += (ground_truth[i].translation_m - ground_truth[i - 1].translation_m).norm();
    if (i == 0 || since_m >= kKeyframeSpacingM - 1e-9) {
      since_m = 0;
      run.keyframe_poses.push_back(ground_truth[i].pose());
      run.keyframe_times.push_back(ground_truth[i].time);
      run.keyframe_segment.push_back(sample_segment[i]);
    }
  }
}

/// Rendered depth of every keyframe (for view overlap), as a dataset's depth list and PNGs.
void render_keyframe_depth(const DatasetCalibration& calibration, LadderRun& run) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_file((run.dataset_dir / "scene.yaml").string());
  const sim::world::World world = sim::world::generate_world(scene);
  sim::render::RgbdRenderer renderer(calibration.intrinsics);
  renderer.set_world(world, scene);
  std::ofstream list(run.dataset_dir / "depth.txt");
  list << "# depth maps of the keyframes\n";
  sim::render::RenderedView view;
  for (std::size_t k = 0; k < run.keyframe_poses.size(); ++k) {
    renderer.render(run.keyframe_poses[k], view);
    cv::Mat depth_m = view.depth_m.clone();
    depth_m.setTo(0.0f, depth_m > kSensorMaxRangeM);
    const std::string name = "depth/" + run.keyframe_times[k].to_string(6) + ".png";
    sim::render::write_depth_png(run.dataset_dir / name, depth_m);
    list << run.keyframe_times[k].to_string(6) << " " << name << "\n";
  }
}

/// The run: a perfect estimate in its own map frame, its keyframes, a timing.json and run.json.
void write_perfect_run(const Trajectory& ground_truth, const LadderRun& run) {
  Trajectory estimated, keyframes;
  for (const StampedPose& g : ground_truth) {
    estimated.push_back(StampedPose::from_pose(g.time, map_from_world() * g.pose()));
  }
  for (std::size_t k = 0; k < run.keyframe_poses.size(); ++k) {
    keyframes.push_back(
        StampedPose::from_pose(run.keyframe_times[k], map_from_world() * run.keyframe_poses[k]));
  }
  write_tum_trajectory((run.run_dir / "trajectory.txt").string(), estimated);
  write_tum_trajectory((run.run_dir / "keyframes.txt").string(), keyframes);
  std::ofstream(run.run_dir / "timing.json") << R"({
 "counters": {"candidate_comparisons": 120, "keyframes": )"
                                             << keyframes.size() << R"(},
 "keyframe_searches": [],
 "modules": {"loop_closure_detection": {"calls": 10, "total_s": 1.5},
             "optimisation": {"calls": 2, "total_s": 0.25},
             "total": {"calls": 50, "total_s": 4.0}},
 "wall_s": 5.0
})";
  std::ofstream(run.run_dir / "run.json") << R"({"frontend": "rgbdslam"})";
  write_loop_closures(run, {});
}

}  // namespace

LadderRun build_ladder_run(const fs::path& root, bool depth) {
  fs::remove_all(root);
  LadderRun run;
  run.dataset_dir = root / "dataset";
  run.run_dir = root / "run";
  fs::create_directories(run.dataset_dir / "depth");
  fs::create_directories(run.run_dir);
  std::vector<std::string> sample_segment;
  const Trajectory ground_truth = ladder_ground_truth(sample_segment);
  write_tum_trajectory((run.dataset_dir / "groundtruth.txt").string(), ground_truth);
  pick_keyframes(ground_truth, sample_segment, run);
  DatasetCalibration calibration;
  calibration.intrinsics = small_intrinsics();
  std::ofstream(run.dataset_dir / "calibration.yaml") << calibration_to_yaml(calibration);
  fs::copy_file(fs::path(WIFISLAM_SCENES_DIR) / "aliasing_ladder.yaml",
                run.dataset_dir / "scene.yaml");
  if (depth) render_keyframe_depth(calibration, run);
  write_perfect_run(ground_truth, run);
  return run;
}

void write_loop_closures(const LadderRun& run, const std::vector<LoopClosureRow>& rows) {
  std::ofstream out(run.run_dir / "loop_closures.csv");
  out << "from_keyframe,to_keyframe,from_frame,to_frame,from_time,to_time,role,inliers,"
         "rms_reprojection_px,tx,ty,tz,qx,qy,qz,qw\n";
  for (const LoopClosureRow& r : rows) {
    const Eigen::Quaterniond q(r.from_to.linear());
    const Eigen::Vector3d t = r.from_to.translation();
    out << fmt::format("{},{},{},{},{},{},sampled,60,0.9,{},{},{},{},{},{},{}\n", r.from, r.to,
                       r.from, r.to,
                       run.keyframe_times[static_cast<std::size_t>(r.from)].to_string(6),
                       run.keyframe_times[static_cast<std::size_t>(r.to)].to_string(6), t.x(),
                       t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  }
}

}  // namespace wifislam::test

namespace wifislam::test {

namespace {
nlohmann::json edge_json(int from, int to, const char* type, const Pose& from_to, int pruned) {
  const Eigen::Quaterniond q(from_to.linear());
  const Eigen::Vector3d t = from_to.translation();
  nlohmann::json e = {
      {"from", from},
      {"to", to},
      {"type", type},
      {"inliers", 60},
      {"from_to", {{"t", {t.x(), t.y(), t.z()}}, {"q_xyzw", {q.x(), q.y(), q.z(), q.w()}}}},
      {"information", std::vector<double>(36, 0.0)}};
  if (pruned >= 0) e["pruned"] = pruned == 1;
  return e;
}
}  // namespace

void write_graph(const LadderRun& run, const std::vector<GraphEdgeRow>& edges) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t k = 1; k < run.keyframe_poses.size(); ++k) {
    const int from = static_cast<int>(k) - 1, to = static_cast<int>(k);
    list.push_back(edge_json(from, to, "odometry", run.true_relative(from, to), -1));
  }
  for (const GraphEdgeRow& e : edges)
    list.push_back(edge_json(e.from, e.to, e.type, e.from_to, e.pruned));
  std::ofstream(run.run_dir / "graph.json")
      << nlohmann::json{{"nodes", nlohmann::json::array()}, {"edges", list}}.dump(1);
}

}  // namespace wifislam::test
