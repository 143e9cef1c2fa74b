#pragma once
// Options and summary of dataset generation (Ceres style: every field has its default and says
// what it trades off; the CLI only fills these in).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/sensor_stream.hpp"
#include "core/timestamp.hpp"
#include "sim/render/rgbd_renderer.hpp"

namespace wifislam::sim::generate {

/// What a generation keeps of the camera: one choice where three linked booleans (images, frames,
/// colour images) used to allow combinations that meant nothing.
enum class CameraOutput {
  /// rgb/ and depth/ PNGs (the default).
  kColourAndDepth,
  /// depth/ only: rgb/, rgb.txt and associations.txt absent; the manifest says so and SLAM refuses
  /// such a dataset. For a dataset nobody reads but the evaluation, whose overlap test needs
  /// depth: a study case's, whose SLAM runs take their frames from `on_event`.
  kDepthOnly,
  /// No images: poses, odometry and Wi-Fi only (no rendering; fast radio studies). The in-memory
  /// pipeline still emits each camera frame, without pixels.
  kNoImages,
  /// No images and no camera frames in memory either: odometry and scans only, which are the same
  /// with or without frames (radio-level studies).
  kNoFrames,
};

struct GenerateProgress {
  std::int64_t frames_done = 0;
  std::int64_t frames_total = 0;
  double elapsed_s = 0.0;
};

/// A frame limit: none (negative) or at least one frame. Zero would make a dataset of no frames,
/// which no reader takes (`check` refuses it), or a SLAM run on nothing.
inline void check_max_frames(std::int64_t max_frames) {
  if (max_frames == 0) {
    throw InvalidInputError(
        "max_frames: expected at least 1 frame (or no limit: the whole route), got 0");
  }
}

struct GenerateOptions {
  /// Replaces the scene's seed (world, access points, noise, pauses: everything random).
  std::optional<std::uint64_t> seed;
  /// Replaces sensors.camera.fps. 30 is the Kinect's rate; a lower rate gives proportionally
  /// fewer frames (and smaller datasets) over the same route, with larger motion between frames.
  std::optional<double> fps;
  /// Stop after this many frames (< 0: the whole route). Odometry and scans stop there too.
  std::int64_t max_frames = -1;
  CameraOutput camera = CameraOutput::kColourAndDepth;
  /// Rendered images are written (colour and depth, or depth only).
  bool images() const {
    return camera == CameraOutput::kColourAndDepth || camera == CameraOutput::kDepthOnly;
  }
  bool colour_images() const { return camera == CameraOutput::kColourAndDepth; }
  /// Camera frames are emitted (with or without pixels).
  bool frames() const { return camera != CameraOutput::kNoFrames; }
  /// Called from the generating thread with every event, in time order, exactly as SLAM would
  /// read it back from the dataset being written (frames: colour as written, depth at the PNG's
  /// resolution): lets SLAM runs consume a dataset while it is written, with no PNG round trip
  /// (study/streamed_runs.hpp). Needs images().
  std::function<void(SensorEvent)> on_event;
  /// Threads encoding and writing PNGs while the main thread renders (1 = encode inline;
  /// 0 = one per core). Clamped to 4 per core, and fewer when a process or memory limit will
  /// not start more (GenerateSummary::threads says how many ran). The output is byte-identical
  /// whatever the count.
  int threads = 0;
  /// Replace an existing output folder (only one that looks like this tool's output, and never
  /// `/`, the current directory or the home folder: core/output_folder.hpp).
  bool overwrite = false;
  /// Renderer settings (near/far planes, lighting).
  render::RenderOptions render;
  /// Called after each frame is written, from the calling thread (progress bars).
  std::function<void(const GenerateProgress&)> on_progress;
};

/// What a generation did and where its time went.
struct GenerateSummary {
  std::filesystem::path output;
  std::string scene_name;
  std::uint64_t seed = 0;
  double fps = 0.0;
  std::uint64_t time_origin_s = 0;  // Unix time of the route's start (sensors.time_origin_s)
  Timestamp first_time, last_time;  // the first and last stamp written (any sensor)
  bool images = true;
  int threads = 1;
  std::int64_t frames = 0;
  std::int64_t odometry_readings = 0;
  std::int64_t imu_samples = 0;
  std::int64_t wifi_scans = 0;        // scans with at least one reading (wifi.csv's scans)
  std::int64_t wifi_scans_empty = 0;  // scans that heard no access point (no row in wifi.csv)
  std::int64_t wifi_requests_throttled = 0;  // scan requests the device's throttle refused
  std::string wifi_device;                   // the receiver's name (radio_model/receiver_device)
  std::int64_t wifi_readings = 0;
  std::int64_t pauses = 0;
  std::int64_t access_points = 0;
  std::int64_t bssids = 0;
  /// Distinct access points (BSSIDs aggregated by their last nibble) heard over each pause's
  /// scans: the paper's signature size.
  double aps_heard_per_pause_mean = 0.0;
  std::int64_t aps_heard_per_pause_min = 0, aps_heard_per_pause_max = 0;
  double duration_s = 0.0;      // simulated time covered
  double route_length_m = 0.0;  // travelled (less than the route with max_frames)
  std::uint64_t bytes_written = 0;

  // Wall-clock seconds by stage. png_encode_s and io_s sum over threads (CPU time spent), so with
  // several threads they can exceed total_s.
  double world_s = 0.0;   // world generation, renderer and radio set-up
  double render_s = 0.0;  // OSMesa render + readback
  double sensor_s = 0.0;  // depth sensor model
  double radio_s = 0.0;   // Wi-Fi scans
  double png_encode_s = 0.0;
  double io_s = 0.0;  // writing images, text files, hashing
  double total_s = 0.0;

  double frames_per_second() const { return total_s > 0 ? frames / total_s : 0.0; }
  /// Human-readable, one item per line.
  std::string full_report() const;
};

}  // namespace wifislam::sim::generate
