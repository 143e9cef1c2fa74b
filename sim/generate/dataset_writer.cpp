#include "sim/generate/dataset_writer.hpp"

#include <chrono>
#include <deque>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <opencv2/core/version.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_calibration.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_manifest.hpp"
#include "core/error.hpp"
#include "core/imu_csv.hpp"
#include "core/imu_groundtruth_csv.hpp"
#include "core/png_codec.hpp"
#include "core/text_lines.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "core/wall_clock.hpp"
#include "core/wifi_csv.hpp"
#include "core/worker_pool.hpp"
#include "radio_model/radio_band.hpp"
#include "sim/generate/as_stored.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/robot/imu_model.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::sim::generate {

namespace fs = std::filesystem;

namespace {

/// A text file of the dataset, written sequentially through a large buffer.
class TextOutput {
 public:
  TextOutput(const fs::path& path, std::string header = {})
      : path_(path), out_(path, std::ios::binary) {
    if (!out_) throw IoError(path.string() + ": cannot open for writing");
    out_ << header;
  }
  void write(std::string_view text) {
    out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  void close() {
    out_.close();
    if (!out_) throw IoError(path_.string() + ": write failed (disk full?)");
  }

 private:
  fs::path path_;
  std::ofstream out_;
};

/// What a worker returns for one frame.
struct WrittenFrame {
  std::string rgb_sha256, depth_sha256;
  std::uint64_t bytes = 0;
  double encode_s = 0.0, io_s = 0.0;
};

/// Encodes and writes a frame's PNGs. `depth`: metres (CV_32FC1) or PNG units (CV_16UC1, when
/// the writer converted them already); `rgb` empty: depth only (a depth-only dataset).
WrittenFrame encode_and_write(const fs::path& folder, const std::string& rgb_path,
                              const std::string& depth_path, const cv::Mat& rgb,
                              const cv::Mat& depth) {
  WrittenFrame out;
  auto t0 = WallClock::now();
  const std::vector<unsigned char> rgb_png =
      rgb.empty() ? std::vector<unsigned char>{} : encode_png(rgb);
  const std::vector<unsigned char> depth_png =
      encode_png(depth.type() == CV_16UC1 ? depth : depth_to_png_units(depth));
  out.encode_s = seconds_since(t0);
  t0 = WallClock::now();
  for (const auto& [relative, bytes, sha] :
       {std::tuple{&rgb_path, &rgb_png, &out.rgb_sha256},
        std::tuple{&depth_path, &depth_png, &out.depth_sha256}}) {
    if (relative->empty()) continue;
    const std::string_view data(reinterpret_cast<const char*>(bytes->data()), bytes->size());
    std::ofstream file(folder / *relative, std::ios::binary);
    file.write(data.data(), static_cast<std::streamsize>(data.size()));
    file.close();
    if (!file) throw IoError((folder / *relative).string() + ": write failed (disk full?)");
    *sha = sha256_hex(data);
    out.bytes += bytes->size();
  }
  out.io_s = seconds_since(t0);
  return out;
}

std::string bool_text(bool b) { return b ? "true" : "false"; }

DatasetCalibration make_calibration(const GenerationPipeline& pipeline,
                                    const GenerateOptions& options) {
  const scene::Scene& s = pipeline.scene();
  DatasetCalibration c;
  c.intrinsics = s.sensors.camera.intrinsics;
  c.camera_fps = s.sensors.camera.fps;
  c.depth_units_per_metre = dataset::kDepthUnitsPerMetre;
  c.camera_in_base = pipeline.mount().camera_in_base();
  c.odometry_rate_hz = s.sensors.odometry.rate_hz;
  const scene::DepthSensorSpec& d = s.sensors.depth;
  const auto num = format_double_exact;
  c.sensor_model.push_back({"depth_sensor",
                            {{"min_range_m", num(d.min_range_m)},
                             {"max_range_m", num(d.max_range_m)},
                             {"noise", bool_text(d.noise)},
                             {"quantisation", bool_text(d.quantisation)},
                             {"dropouts", bool_text(d.dropouts)},
                             {"axial_noise_coeff_per_m", num(d.axial_noise_coeff_per_m)},
                             {"baseline_m", num(d.baseline_m)},
                             {"disparity_step_px", num(d.disparity_step_px)},
                             {"grazing_dropout_deg", num(d.grazing_dropout_deg)},
                             {"edge_jump_fraction", num(d.edge_jump_fraction)}}});
  c.sensor_model.push_back(
      {"render", {{"near_m", num(options.render.near_m)}, {"far_m", num(options.render.far_m)}}});
  const scene::WifiScannerSpec& w = s.sensors.wifi;
  const radio_model::ReceiverDevice device = scene::receiver_device(w);
  c.sensor_model.push_back({"wifi_scanner",
                            {{"device", device.name},
                             {"sensitivity_dbm", num(device.sensitivity_dbm)},
                             {"dwell_per_channel_s", num(device.dwell_per_channel_s)},
                             {"rss_offset_db", num(device.rss_offset_db)},
                             {"rss_gain", num(device.rss_gain)},
                             {"rss_gain_pivot_dbm", num(radio_model::kGainPivotDbm)},
                             {"quantisation_db", std::to_string(device.quantisation_db)},
                             {"bands", std::string(to_string(device.bands))},
                             {"scan_throttle", std::string(to_string(device.scan_throttle))},
                             {"scan_interval_s", num(w.scan_interval_s)},
                             {"scan_duration_s", num(pipeline.scanner().scan_duration_ns() * 1e-9)},
                             {"antenna_height_m", num(s.sensors.camera.height_m)}}});
  const world::World& world = pipeline.site().world();
  if (!world.storeys.empty()) {
    // A building of several levels: access_points.csv's z is the building's, the poses' the
    // route level's, whose floor stands at this elevation.
    c.sensor_model.push_back({"building_level",
                              {{"level", world.level_id},
                               {"floor_elevation_m", num(world.elevation_m)},
                               {"levels", std::to_string(world.storeys.size())}}});
  }
  const scene::OdometrySpec& o = s.sensors.odometry;
  c.sensor_model.push_back({"wheel_odometry",
                            {{"noise_per_m", num(o.noise_per_m)},
                             {"noise_per_rad", num(o.noise_per_rad)},
                             {"scale_error", num(o.scale_error)},
                             {"yaw_bias_radpm", num(o.yaw_bias_radpm)}}});
  const scene::ImuSpec& imu = s.sensors.imu;
  if (imu.enabled) {
    ImuCalibration i;
    i.rate_hz = imu.rate_hz;
    i.imu_in_base = robot::ImuModel(pipeline.motion(), imu, scene::session_seed(s)).imu_in_base();
    i.gyroscope_noise_density = imu.gyroscope_noise_density;
    i.gyroscope_random_walk = imu.gyroscope_random_walk;
    i.accelerometer_noise_density = imu.accelerometer_noise_density;
    i.accelerometer_random_walk = imu.accelerometer_random_walk;
    c.imu = i;
  }
  return c;
}

std::string access_points_csv(const radio_model::PropagationModel& radio) {
  std::string out = "ap_id,x_m,y_m,z_m,tx_power_dbm,bssid,ssid,band,channel,frequency_khz\n";
  for (const radio_model::AccessPoint& ap : radio.access_points()) {
    for (const radio_model::Bssid& b : ap.bssids) {
      out += fmt::format(
          "{},{},{},{},{},{},{},{},{},{}\n", ap.id, format_double_exact(ap.position_m.x()),
          format_double_exact(ap.position_m.y()), format_double_exact(ap.position_m.z()),
          format_double_exact(ap.tx_power_dbm), b.mac.to_string(), b.ssid, to_string(b.band),
          b.channel, b.frequency_khz);
    }
  }
  return out;
}

std::string parameters_json(const scene::Scene& scene, const GenerateOptions& options) {
  // The recording first (scene, seed, session, fps, time origin): what run.json records of its
  // input and eval compares (core/dataset_recording.hpp).
  nlohmann::ordered_json p = recording_json(recording_of_scene(scene));
  const radio_model::ReceiverDevice device = scene::receiver_device(scene.sensors.wifi);
  p["wifi_device"] = {{"name", device.name}, {"source", device.source}};
  p["max_frames"] = options.max_frames;
  p["images"] = options.images();
  if (options.camera == CameraOutput::kDepthOnly)
    p["colour_images"] = false;  // absent (true) in every other dataset
  p["render"] = {{"near_m", options.render.near_m},
                 {"far_m", options.render.far_m},
                 {"ambient", options.render.ambient},
                 {"light_power", options.render.light_power},
                 {"max_lights", options.render.max_lights},
                 {"light_range_m", options.render.light_range_m},
                 {"frustum_culling", options.render.frustum_culling}};
  return p.dump();
}

/// Writes one dataset from a pipeline into the staging folder of `folder`, streaming: the calling
/// thread takes the pipeline's events in time order (rendering happens there) and writes the text
/// files; PNG encoding runs on the worker pool, and each frame's list lines are written when its
/// images are done, oldest first, so every byte is the same whatever the thread count.
class DatasetWriter {
 public:
  DatasetWriter(GenerationPipeline& pipeline, AtomicDirectory& folder,
                const GenerateOptions& options, WallClock::time_point start)
      : pipeline_(pipeline),
        folder_(folder),
        dir_(folder.staging_path()),
        options_(options),
        start_(start),
        groundtruth_(dir_ / dataset::kGroundTruth,
                     fmt::format("# ground truth trajectory\n# file: '{}'\n# timestamp tx ty tz "
                                 "qx qy qz qw (camera optical frame to world)\n",
                                 pipeline.scene().name)),
        odometry_(dir_ / dataset::kOdometry,
                  "# wheel odometry: robot base in the odometry frame (calibration.yaml: "
                  "camera_in_base)\n# timestamp tx ty tz qx qy qz qw\n"),
        wifi_(dir_ / dataset::kWifi, wifi_csv_header() + "\n") {}

  GenerateSummary write() {
    describe_scene();
    const auto t_io = WallClock::now();
    write_scene_files();
    summary_.io_s += seconds_since(t_io);
    start_encoders();
    while (auto generated = pipeline_.next()) take(*generated);
    while (!pending_.empty()) collect_oldest();
    pool_.reset();
    write_imu();
    for (const robot::RobotPause& p : pipeline_.motion().pauses())
      summary_.pauses += p.start <= pipeline_.schedule().end_time();
    summary_.wifi_requests_throttled = pipeline_.schedule().throttled_requests();
    summary_.wifi_device = pipeline_.scanner().options().device.name;
    finish();
    return summary_;
  }

 private:
  /// A frame whose images are being encoded, oldest first.
  struct Pending {
    FramePair pair;
    std::future<WrittenFrame> result;
  };

  void describe_scene() {
    const scene::Scene& scene = pipeline_.scene();
    summary_.output = folder_.final_path();
    summary_.scene_name = scene.name;
    summary_.seed = scene.seed;
    summary_.fps = scene.sensors.camera.fps;
    summary_.time_origin_s = scene.sensors.time_origin_s;
    summary_.images = options_.images();
    summary_.access_points = static_cast<std::int64_t>(pipeline_.radio().access_points().size());
    for (const radio_model::AccessPoint& ap : pipeline_.radio().access_points())
      summary_.bssids += static_cast<std::int64_t>(ap.bssids.size());
  }

  void write_scene_files() {
    const scene::Scene& scene = pipeline_.scene();
    write_file_atomic(dir_ / dataset::kScene, scene::resolved_scene_yaml(scene));
    write_file_atomic(dir_ / dataset::kCalibration,
                      calibration_to_yaml(make_calibration(pipeline_, options_)));
    write_file_atomic(dir_ / dataset::kAccessPoints, access_points_csv(pipeline_.radio()));
    if (!options_.images()) return;
    const std::string name = scene.name + " (wifislam)";
    if (options_.colour_images()) {
      fs::create_directories(dir_ / dataset::kRgbDir);
      rgb_list_.emplace(dir_ / dataset::kRgbList,
                        fmt::format("# color images\n# file: '{}'\n# timestamp filename\n", name));
      associations_.emplace(dir_ / dataset::kAssociations);
    }
    fs::create_directories(dir_ / dataset::kDepthDir);
    depth_list_.emplace(dir_ / dataset::kDepthList,
                        fmt::format("# depth maps\n# file: '{}'\n# timestamp filename\n", name));
    image_sums_.emplace(dir_ / dataset::kImageChecksums);
  }

  void start_encoders() {
    int threads = clamp_thread_count(options_.threads);
    if (options_.images() && threads > 1) {
      pool_.emplace(threads);
      // A process or memory limit may allow fewer threads: encode with those, or inline.
      threads = std::max(1, pool_->size());
      if (pool_->size() == 0) pool_.reset();
    }
    summary_.threads = options_.images() ? threads : 1;
    max_pending_ = static_cast<std::size_t>(2 * threads);
  }

  void take(GeneratedEvent& generated) {
    const Timestamp t = event_time(generated.event);
    if (!any_event_) summary_.first_time = t;
    summary_.last_time = t;
    any_event_ = true;
    if (const auto* reading = std::get_if<OdometryReading>(&generated.event)) {
      odometry_.write(
          format_tum_line(StampedPose::from_pose(reading->time, reading->base_in_odom)));
      odometry_.write("\n");
      ++summary_.odometry_readings;
      if (options_.on_event) options_.on_event(odometry_as_stored(*reading));
    } else if (const auto* scan = std::get_if<WifiScan>(&generated.event)) {
      take_scan(*scan);
      if (options_.on_event) options_.on_event(generated.event);
    } else {
      take_frame(std::get<RgbdFrame>(generated.event), generated.camera_to_world);
    }
  }

  /// imu.csv: every IMU sample up to the run's end, on the events' clock. Not an event of the
  /// stream: nothing we run reads it, and 200 rows a second would only slow the stream down.
  void write_imu() {
    const scene::Scene& scene = pipeline_.scene();
    if (!scene.sensors.imu.enabled) return;
    const auto t_io = WallClock::now();
    robot::ImuModel imu(pipeline_.motion(), scene.sensors.imu, scene::session_seed(scene));
    TextOutput out(dir_ / dataset::kImu, imu_csv_header() + "\n");
    TextOutput truth(dir_ / dataset::kImuGroundTruth, imu_groundtruth_csv_header() + "\n");
    const robot::SensorSchedule& schedule = pipeline_.schedule();
    const std::int64_t n = imu.sample_count(schedule.end_time());
    const auto on_clock = [&](Timestamp route_time) {
      return Timestamp::from_ns(route_time.ns + pipeline_.time_origin().ns);
    };
    // The true state at each frame time, with the biases of the sample at or before it.
    std::int64_t frame = 0;
    const auto state_rows_up_to = [&](Timestamp before) {
      for (; frame < schedule.frame_count() && schedule.frame_time(frame) < before; ++frame) {
        const Timestamp t = schedule.frame_time(frame);
        const robot::ImuState state = imu.true_state(t);
        truth.write(
            format_imu_groundtruth_csv_row({on_clock(t), state.imu_to_world, state.velocity_mps,
                                            imu.gyro_bias_radps(), imu.accel_bias_mps2()}));
      }
    };
    for (std::int64_t k = 0; k < n; ++k) {
      state_rows_up_to(imu.sample_time(k));
      ImuReading reading = imu.measure(k);
      reading.time = on_clock(reading.time);
      out.write(format_imu_csv_row(reading));
    }
    state_rows_up_to(Timestamp::from_ns(std::numeric_limits<std::int64_t>::max()));
    out.close();
    truth.close();
    summary_.imu_samples = n;
    summary_.io_s += seconds_since(t_io);
  }

  void take_scan(const WifiScan& scan) {
    wifi_.write(format_wifi_csv_rows(scan));
    // wifi.csv has one row per reading, so a scan that heard nothing leaves no trace in it:
    // the manifest counts the scans the file holds, and the silent ones apart.
    if (scan.readings.empty()) {
      ++summary_.wifi_scans_empty;
    } else {
      ++summary_.wifi_scans;
    }
    summary_.wifi_readings += static_cast<std::int64_t>(scan.readings.size());
    const int pause = pipeline_.schedule().scans()[scan_index_++].pause_index;
    if (pause >= 0) {
      auto& heard = aps_by_pause_[pause];
      for (const WifiReading& r : scan.readings) heard.insert(r.bssid.without_last_nibble());
    }
  }

  void take_frame(RgbdFrame& frame, const Pose& camera_to_world) {
    groundtruth_.write(format_tum_line(StampedPose::from_pose(frame.time, camera_to_world)));
    groundtruth_.write("\n");
    ++summary_.frames;
    if (!options_.images()) {
      report_progress();
      return;
    }
    const FramePair pair{
        frame.time,
        options_.colour_images() ? dataset::frame_image_path(dataset::kRgbDir, frame.time) : "",
        frame.time, dataset::frame_image_path(dataset::kDepthDir, frame.time), 0};
    // Depth goes to the encoder in metres (converted there, off this thread) unless the frame is
    // also streamed: then its PNG units are made once, here, for both.
    cv::Mat depth = std::move(frame.depth_m);
    if (options_.on_event) {
      depth = depth_to_png_units(depth);
      // What a reader decodes: the colour image as is (PNG is lossless), depth from its units.
      RgbdFrame as_read = frame;
      as_read.depth_m = depth_as_stored(depth);
      options_.on_event(std::move(as_read));
    }
    cv::Mat rgb = options_.colour_images() ? std::move(frame.rgb) : cv::Mat();
    if (!pool_) {
      finish_frame(pair, encode_and_write(dir_, pair.rgb_path, pair.depth_path, rgb, depth));
      report_progress();
      return;
    }
    while (pending_.size() >= max_pending_) collect_oldest();
    pending_.push_back(
        {pair, pool_->submit([dir = dir_, pair, rgb = std::move(rgb), depth = std::move(depth)] {
           return encode_and_write(dir, pair.rgb_path, pair.depth_path, rgb, depth);
         })});
  }

  void finish_frame(const FramePair& pair, const WrittenFrame& written) {
    summary_.png_encode_s += written.encode_s;
    summary_.io_s += written.io_s;
    summary_.bytes_written += written.bytes;
    if (rgb_list_) rgb_list_->write(format_tum_file_line(pair.rgb_time, pair.rgb_path));
    depth_list_->write(format_tum_file_line(pair.depth_time, pair.depth_path));
    if (associations_) associations_->write(format_association_line(pair));
    if (!pair.rgb_path.empty())
      image_sums_->write(format_checksum_line(written.rgb_sha256, pair.rgb_path));
    image_sums_->write(format_checksum_line(written.depth_sha256, pair.depth_path));
  }

  void collect_oldest() {
    Pending p = std::move(pending_.front());
    pending_.pop_front();
    finish_frame(p.pair, p.result.get());
    report_progress();
  }

  void report_progress() {
    ++frames_done_;
    if (options_.on_progress) {
      options_.on_progress(
          {frames_done_, pipeline_.schedule().frame_count(), seconds_since(start_)});
    }
  }

  /// Closes the files, writes the manifest (last: its presence marks a finished dataset),
  /// commits the folder and completes the summary.
  void finish() {
    const auto t_io = WallClock::now();
    for (TextOutput* out : {&groundtruth_, &odometry_, &wifi_}) out->close();
    for (auto* out : {&rgb_list_, &depth_list_, &associations_, &image_sums_})
      if (*out) (*out)->close();
    const std::string manifest_text = manifest_to_json(make_manifest());
    write_file_atomic(dir_ / dataset::kManifest, manifest_text);
    summary_.bytes_written += manifest_text.size();
    folder_.commit();
    summary_.io_s += seconds_since(t_io);
    summarise_pauses();
    summary_.duration_s = pipeline_.schedule().end_time().seconds();
    summary_.route_length_m =
        pipeline_.motion().state_at(pipeline_.schedule().end_time()).arc_length_m;
    summary_.world_s = pipeline_.timings().setup_s;
    summary_.render_s = pipeline_.timings().render_s;
    summary_.sensor_s = pipeline_.timings().sensor_s;
    summary_.radio_s = pipeline_.timings().radio_s;
    summary_.total_s = seconds_since(start_);
  }

  DatasetManifest make_manifest() {
    DatasetManifest manifest;
    manifest.images = options_.images();
    manifest.colour_images = options_.camera != CameraOutput::kDepthOnly;  // false: depth only
    manifest.versions = {{"wifislam", WIFISLAM_VERSION},
                         {"opencv", CV_VERSION},
                         {"eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
                                               EIGEN_MINOR_VERSION)}};
    manifest.parameters_json = parameters_json(pipeline_.scene(), options_);
    manifest.counts = {{"frames", options_.images() ? summary_.frames : 0},
                       {"groundtruth_poses", summary_.frames},
                       {"odometry_readings", summary_.odometry_readings},
                       {"imu_samples", summary_.imu_samples},
                       {"wifi_scans", summary_.wifi_scans},
                       {"wifi_scans_that_heard_nothing", summary_.wifi_scans_empty},
                       {"wifi_scan_requests_throttled", summary_.wifi_requests_throttled},
                       {"wifi_readings", summary_.wifi_readings},
                       {"pauses", summary_.pauses},
                       {"access_points", summary_.access_points},
                       {"bssids", summary_.bssids}};
    std::vector<std::string> files;
    if (options_.images() && options_.colour_images()) files = {dataset::kRgbList};
    if (options_.images()) files.push_back(dataset::kDepthList);
    if (options_.images() && options_.colour_images()) files.push_back(dataset::kAssociations);
    for (const char* f : {dataset::kGroundTruth, dataset::kOdometry, dataset::kWifi,
                          dataset::kAccessPoints, dataset::kCalibration, dataset::kScene})
      files.push_back(f);
    if (pipeline_.scene().sensors.imu.enabled) {
      files.push_back(dataset::kImu);
      files.push_back(dataset::kImuGroundTruth);
    }
    if (options_.images()) files.push_back(dataset::kImageChecksums);
    for (const std::string& f : files) {
      manifest.files.push_back(describe_dataset_file(dir_, f));
      summary_.bytes_written += manifest.files.back().bytes;
    }
    return manifest;
  }

  /// Access points heard per pause: the paper's signature size.
  void summarise_pauses() {
    if (aps_by_pause_.empty()) return;
    std::int64_t sum = 0;
    summary_.aps_heard_per_pause_min = std::numeric_limits<std::int64_t>::max();
    for (const auto& [pause, heard] : aps_by_pause_) {
      const auto n = static_cast<std::int64_t>(heard.size());
      sum += n;
      summary_.aps_heard_per_pause_min = std::min(summary_.aps_heard_per_pause_min, n);
      summary_.aps_heard_per_pause_max = std::max(summary_.aps_heard_per_pause_max, n);
    }
    summary_.aps_heard_per_pause_mean = static_cast<double>(sum) / aps_by_pause_.size();
  }

  GenerationPipeline& pipeline_;
  AtomicDirectory& folder_;
  const fs::path dir_;
  const GenerateOptions& options_;
  const WallClock::time_point start_;
  GenerateSummary summary_;
  TextOutput groundtruth_, odometry_, wifi_;
  std::optional<TextOutput> rgb_list_, depth_list_, associations_, image_sums_;
  std::optional<WorkerPool> pool_;
  std::deque<Pending> pending_;
  std::size_t max_pending_ = 2;
  std::int64_t frames_done_ = 0;
  std::map<int, std::set<MacAddress>> aps_by_pause_;
  std::size_t scan_index_ = 0;
  bool any_event_ = false;
};

/// Options that only make sense with images.
void check_image_options(const GenerateOptions& options) {
  if (options.images()) return;
  if (options.on_event) throw std::invalid_argument("on_event needs images");
}

}  // namespace

GenerateSummary generate_dataset(const scene::Scene& scene, const fs::path& output,
                                 const GenerateOptions& options) {
  check_image_options(options);
  const auto start = WallClock::now();
  AtomicDirectory folder(output, options.overwrite);
  GenerationPipeline pipeline(resolve_scene(scene, options), options);
  return DatasetWriter(pipeline, folder, options, start).write();
}

GenerateSummary generate_dataset(std::shared_ptr<const site::Site> site, const fs::path& output,
                                 const GenerateOptions& options) {
  check_image_options(options);
  const auto start = WallClock::now();
  AtomicDirectory folder(output, options.overwrite);
  GenerationPipeline pipeline(std::move(site), options);
  return DatasetWriter(pipeline, folder, options, start).write();
}

std::string GenerateSummary::full_report() const {
  std::string r;
  r += fmt::format("dataset           {}\n", output.string());
  r += fmt::format("scene             {} (seed {})\n", scene_name, seed);
  r += fmt::format("frames            {}{} at {} fps, {:.1f} s simulated, {:.1f} m travelled\n",
                   frames, images ? "" : " (poses only, no images)", fps, duration_s,
                   route_length_m);
  r += fmt::format("time origin       {} s Unix time (sensors.time_origin_s); stamps {} .. {}\n",
                   time_origin_s, first_time.to_tum_string(), last_time.to_tum_string());
  r += fmt::format("pauses            {}\n", pauses);
  r += fmt::format(
      "wifi scans        {} ({} readings){}{}\n", wifi_scans, wifi_readings,
      wifi_scans_empty > 0 ? fmt::format("; {} more heard no access point", wifi_scans_empty)
                           : std::string(),
      wifi_requests_throttled > 0 ? fmt::format("; {} requests refused by {}'s throttle",
                                                wifi_requests_throttled, wifi_device)
                                  : std::string());
  r += fmt::format(
      "access points     {} ({} BSSIDs); heard per pause: mean {:.1f}, min {}, max {}\n",
      access_points, bssids, aps_heard_per_pause_mean, aps_heard_per_pause_min,
      aps_heard_per_pause_max);
  r += fmt::format("odometry          {} readings\n", odometry_readings);
  if (imu_samples > 0) r += fmt::format("imu               {} samples\n", imu_samples);
  r += fmt::format("size              {:.1f} MB\n", bytes_written / 1e6);
  r += fmt::format("time              {:.2f} s total, {:.1f} frames/s ({} thread{})\n", total_s,
                   frames_per_second(), threads, threads == 1 ? "" : "s");
  r += fmt::format("  set-up          {:.2f} s (world, renderer, radio)\n", world_s);
  r += fmt::format("  render          {:.2f} s\n", render_s);
  r += fmt::format("  sensor model    {:.2f} s\n", sensor_s);
  r += fmt::format("  radio           {:.2f} s\n", radio_s);
  r += fmt::format("  png encode      {:.2f} s (summed over threads)\n", png_encode_s);
  r += fmt::format("  i/o             {:.2f} s (summed over threads)\n", io_s);
  return r;
}

}  // namespace wifislam::sim::generate
