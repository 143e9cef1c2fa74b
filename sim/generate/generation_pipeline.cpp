#include "sim/generate/generation_pipeline.hpp"

#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/wall_clock.hpp"
#include "sim/site/radio_options.hpp"

namespace wifislam::sim::generate {

namespace {

std::shared_ptr<const site::Site> timed_site(const scene::Scene& scene, double& seconds) {
  const auto t0 = WallClock::now();
  auto site = std::make_shared<const site::Site>(scene);  // validates the scene
  seconds = seconds_since(t0);
  return site;
}

}  // namespace

scene::Scene resolve_scene(const scene::Scene& scene, const GenerateOptions& options) {
  check_max_frames(options.max_frames);
  scene::Scene out = scene;
  if (options.seed) out.seed = *options.seed;
  if (options.fps) {
    if (!(*options.fps >= scene::kMinCameraFps && *options.fps <= scene::kMaxCameraFps)) {
      throw InvalidInputError(fmt::format("fps: expected a frame rate from {} to {}, got {}",
                                          scene::kMinCameraFps, scene::kMaxCameraFps,
                                          *options.fps));
    }
    out.sensors.camera.fps = *options.fps;
  }
  return out;
}

DatasetRecording recording_of_scene(const scene::Scene& resolved) {
  DatasetRecording r;
  r.scene = resolved.name;
  r.seed = resolved.seed;
  r.session = resolved.session;
  r.fps = resolved.sensors.camera.fps;
  r.time_origin_s = resolved.sensors.time_origin_s;
  return r;
}

GenerationPipeline::GenerationPipeline(const scene::Scene& scene, const GenerateOptions& options)
    : site_(timed_site(scene, site_build_s_)),
      scene_(site_->scene()),
      mount_(scene_.sensors.camera) {
  set_up(options);
}

GenerationPipeline::GenerationPipeline(std::shared_ptr<const site::Site> site,
                                       const GenerateOptions& options)
    : site_(std::move(site)), scene_(site_->scene()), mount_(scene_.sensors.camera) {
  if (options.seed || options.fps) {
    throw std::invalid_argument(
        "a generation pipeline on a site: apply the seed and fps overrides when building the site "
        "(resolve_scene)");
  }
  set_up(options);
}

void GenerationPipeline::set_up(const GenerateOptions& options) {
  const auto t0 = WallClock::now();
  // The validated origin is before 2100, so whole seconds to nanoseconds cannot overflow.
  time_origin_ =
      Timestamp::from_ns(static_cast<std::int64_t>(scene_.sensors.time_origin_s) * 1'000'000'000);
  scanner_ = std::make_unique<radio_model::WifiScanner>(
      site_->radio(), site::wifi_scanner_options(scene_.sensors.wifi), scene::session_seed(scene_));

  robot::SensorScheduleOptions schedule;
  schedule.fps = scene_.sensors.camera.fps;
  schedule.odometry_rate_hz = scene_.sensors.odometry.rate_hz;
  schedule.scan_interval_s = scene_.sensors.wifi.scan_interval_s;
  schedule.scan_duration_ns = scanner_->scan_duration_ns();
  schedule.scan_while_moving = scene_.route.pause.scan_while_moving;
  const radio_model::ThrottleLimit throttle =
      radio_model::throttle_limit(scanner_->options().device.scan_throttle);
  schedule.throttle_max_scans = throttle.max_scans;
  schedule.throttle_window_s = throttle.window_s;
  schedule.max_frames = options.max_frames;
  schedule_ = std::make_unique<robot::SensorSchedule>(site_->motion(), schedule);
  odometry_ =
      std::make_unique<robot::WheelOdometry>(scene_.sensors.odometry, scene::session_seed(scene_));

  frames_ = options.frames();
  if (options.images()) {
    renderer_ =
        std::make_unique<render::RgbdRenderer>(scene_.sensors.camera.intrinsics, options.render);
    renderer_->set_world(site_->world(), scene_);
    depth_model_ = std::make_unique<render::DepthSensorModel>(
        scene_.sensors.depth, scene_.sensors.camera.intrinsics, scene::session_seed(scene_));
    color_model_ = std::make_unique<render::ColorSensorModel>(
        scene_.sensors.color, scene_.sensors.camera.fps, scene::session_seed(scene_));
  }
  timings_.setup_s = site_build_s_ + seconds_since(t0);
}

GenerationPipeline::~GenerationPipeline() = default;

std::optional<GeneratedEvent> GenerationPipeline::next() {
  constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();
  const auto& scans = schedule_->scans();
  const std::int64_t t_odo = next_odometry_ < schedule_->odometry_count()
                                 ? schedule_->odometry_time(next_odometry_).ns
                                 : kNever;
  const std::int64_t t_scan = next_scan_ < scans.size() ? scans[next_scan_].end.ns : kNever;
  const std::int64_t t_frame = frames_ && next_frame_ < schedule_->frame_count()
                                   ? schedule_->frame_time(next_frame_).ns
                                   : kNever;
  if (t_odo == kNever && t_scan == kNever && t_frame == kNever) return std::nullopt;
  if (t_odo <= t_scan && t_odo <= t_frame) {
    const Timestamp t = Timestamp::from_ns(t_odo);
    ++next_odometry_;
    OdometryReading reading = odometry_->measure(t, site_->motion().state_at(t));
    reading.time = on_event_clock(reading.time);
    return GeneratedEvent{reading};
  }
  if (t_scan <= t_frame) {
    WifiScan scan = make_scan(scans[next_scan_++]);
    for (Timestamp* t : {&scan.time, &scan.start_time, &scan.end_time}) *t = on_event_clock(*t);
    return GeneratedEvent{std::move(scan)};
  }
  GeneratedEvent frame = make_frame(next_frame_++);
  RgbdFrame& f = std::get<RgbdFrame>(frame.event);
  f.time = on_event_clock(f.time);
  return frame;
}

GeneratedEvent GenerationPipeline::make_frame(std::int64_t k) {
  RgbdFrame frame;
  frame.time = schedule_->frame_time(k);
  frame.index = k;
  GeneratedEvent out;
  // Frames are made in order, so a frame submitted ahead is this one.
  out.camera_to_world = submitted_frame_ == k ? submitted_pose_ : camera_pose(k);
  if (renderer_) {
    auto t0 = WallClock::now();
    if (submitted_frame_ != k) renderer_->submit(out.camera_to_world);
    renderer_->collect(view_);
    // The next frame rasterizes on llvmpipe's threads while this one goes through the sensor
    // models and the events up to it are made (its pose is known: the route is planned).
    submitted_frame_ = -1;
    if (k + 1 < schedule_->frame_count()) {
      submitted_pose_ = camera_pose(k + 1);
      renderer_->submit(submitted_pose_);
      submitted_frame_ = k + 1;
    }
    timings_.render_s += seconds_since(t0);
    t0 = WallClock::now();
    color_model_->measure(view_.color_bgr, k, frame.rgb);
    depth_model_->measure(view_.depth_m, view_.incidence_cos, k, frame.depth_m);
    timings_.sensor_s += seconds_since(t0);
  }
  out.event = std::move(frame);
  return out;
}

Pose GenerationPipeline::camera_pose(std::int64_t k) const {
  return mount_.camera_to_world(site_->motion().state_at(schedule_->frame_time(k)));
}

WifiScan GenerationPipeline::make_scan(const robot::ScanWindow& window) {
  const auto t0 = WallClock::now();
  // The radio works in the building's frame: the route level's floor is at its elevation.
  const double antenna_z_m = site_->world().elevation_m + site_->receiver_height_m();
  auto position_at = [&](Timestamp t) {
    const robot::RobotState s = site_->motion().state_at(t);
    return Eigen::Vector3d(s.position_m.x(), s.position_m.y(), antenna_z_m);
  };
  WifiScan scan = window.pause_index >= 0 && scene_.route.pause.scan_while_moving == false
                      ? scanner_->scan(window.start, position_at(window.start))
                      : scanner_->scan(window.start, position_at);
  timings_.radio_s += seconds_since(t0);
  return scan;
}

}  // namespace wifislam::sim::generate
