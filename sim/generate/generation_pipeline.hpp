#pragma once
// The simulation run behind both consumers (the dataset writer and the in-memory stream): it
// builds the world, the robot's motion and sensor schedule, the renderer with its depth sensor
// model, the radio model with its scanner, and the wheel odometry, then produces the sensor
// events in time order (ties: odometry, then Wi-Fi, then the frame, as SensorStream promises):
//
//   frame k:    pose at its time (exact, from the motion profile) -> render -> depth sensor model
//               and colour sensor model (whose auto-exposure carries state from frame k-1 to k;
//               frames are made in order, so it is the same for both consumers). Frame k+1 is
//               submitted to the renderer before frame k's sensor models run, so it rasterizes
//               meanwhile on llvmpipe's threads (same pixels as rendering it when asked)
//   Wi-Fi scan: during pauses (or throughout with scan_while_moving), reported at the sweep's end,
//               the receiver at the robot's position (antenna at the camera's height)
//   odometry:   wheel odometry at its rate
//
// Everything random is seeded from the scene seed through named sub-streams, so the events do
// not depend on threads or on which consumer reads them.
//
// Clocks: the simulation (motion, schedule, fading, odometry) runs on route time, from 0 at the
// route's start; the events next() returns carry Unix time, route time plus the scene's
// sensors.time_origin_s, added in integer nanoseconds (exact). So the origin changes what the
// stamps say and nothing else.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/dataset_recording.hpp"
#include "core/sensor_stream.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "sim/generate/generate_options.hpp"
#include "sim/render/color_sensor_model.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/robot/camera_mount.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/robot/sensor_schedule.hpp"
#include "sim/robot/wheel_odometry.hpp"
#include "sim/scene/scene.hpp"
#include "sim/site/site.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::generate {

/// An event and, for frames, the ground truth that goes with it (never given to SLAM).
struct GeneratedEvent {
  SensorEvent event;
  Pose camera_to_world = Pose::Identity();  // frames only
};

/// Seconds spent per stage so far.
struct PipelineTimings {
  double setup_s = 0.0, render_s = 0.0, sensor_s = 0.0, radio_s = 0.0;
};

class GenerationPipeline {
 public:
  /// `scene` is used as given (apply seed/fps overrides first: resolve_scene()). With
  /// `options.images` false there is no renderer and frames come without images.
  GenerationPipeline(const scene::Scene& scene, const GenerateOptions& options);
  /// On a site built already (its scene is used as given, overrides applied); several pipelines
  /// and the caller may share one site.
  GenerationPipeline(std::shared_ptr<const site::Site> site, const GenerateOptions& options);
  ~GenerationPipeline();

  std::optional<GeneratedEvent> next();

  const scene::Scene& scene() const { return scene_; }
  const site::Site& site() const { return *site_; }
  /// The site, for another pipeline on it.
  std::shared_ptr<const site::Site> shared_site() const { return site_; }
  const world::World& world() const { return site_->world(); }
  const robot::MotionProfile& motion() const { return site_->motion(); }
  const robot::SensorSchedule& schedule() const { return *schedule_; }
  const robot::CameraMount& mount() const { return mount_; }
  const radio_model::PropagationModel& radio() const { return site_->radio(); }
  const radio_model::WifiScanner& scanner() const { return *scanner_; }
  bool images() const { return renderer_ != nullptr; }
  /// The renderer (null without images); benchmarks time it alone as a baseline.
  render::RgbdRenderer* renderer() { return renderer_.get(); }
  const PipelineTimings& timings() const { return timings_; }
  /// Added to route time in every event next() returns (sensors.time_origin_s).
  Timestamp time_origin() const { return time_origin_; }
  /// Route time of an event time (the clock motion() and schedule() run on).
  Timestamp route_time(Timestamp event_time) const {
    return Timestamp::from_ns(event_time.ns - time_origin_.ns);
  }

 private:
  GeneratedEvent make_frame(std::int64_t k);
  Pose camera_pose(std::int64_t frame_index) const;
  WifiScan make_scan(const robot::ScanWindow& window);
  Timestamp on_event_clock(Timestamp route_time) const {
    return Timestamp::from_ns(route_time.ns + time_origin_.ns);
  }

  void set_up(const GenerateOptions& options);

  double site_build_s_ = 0.0;  // building the site, when this pipeline built it (setup_s)
  std::shared_ptr<const site::Site> site_;
  const scene::Scene& scene_;
  std::unique_ptr<robot::SensorSchedule> schedule_;
  robot::CameraMount mount_;
  std::unique_ptr<render::RgbdRenderer> renderer_;
  std::unique_ptr<render::DepthSensorModel> depth_model_;
  std::unique_ptr<render::ColorSensorModel> color_model_;
  std::unique_ptr<radio_model::WifiScanner> scanner_;
  std::unique_ptr<robot::WheelOdometry> odometry_;
  render::RenderedView view_;
  std::int64_t submitted_frame_ = -1;       // the frame the renderer is working on ahead, if any
  Pose submitted_pose_ = Pose::Identity();  // and its camera pose
  std::int64_t next_frame_ = 0, next_odometry_ = 0;
  bool frames_ = true;  // GenerateOptions::frames
  std::size_t next_scan_ = 0;
  PipelineTimings timings_;
  Timestamp time_origin_;
};

/// The scene with the options' seed and fps overrides applied (what scene.yaml records).
scene::Scene resolve_scene(const scene::Scene& scene, const GenerateOptions& options);

/// The recording a dataset of `resolved` (a scene with its overrides applied: resolve_scene, or a
/// site's scene) holds: what its manifest.json's parameters and its runs' run.json record.
DatasetRecording recording_of_scene(const scene::Scene& resolved);

}  // namespace wifislam::sim::generate
