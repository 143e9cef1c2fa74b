#include "slam/system/run_slam.hpp"

#include <chrono>

#include "core/stop_signal.hpp"
#include "core/wall_clock.hpp"

namespace wifislam::slam::system {

std::unique_ptr<SlamSystem> run_slam(SensorStream& stream, const SlamOptions& options,
                                     RunSummary& summary, const FrameProgress& progress,
                                     const feature::FeatureStore* features) {
  const auto start = std::chrono::steady_clock::now();
  StreamInfo info;
  info.intrinsics = stream.intrinsics();
  info.camera_in_base = stream.camera_in_base();
  info.has_wifi = stream.has_wifi();
  info.has_odometry = stream.has_odometry();
  auto system = std::make_unique<SlamSystem>(options, info);
  system->use_feature_store(features);
  std::int64_t frames = 0;
  while (std::optional<SensorEvent> event = stream.next()) {
    // Under a command's StopOnSignal guard (compare, demo), Ctrl-C stops the run at its next
    // event; without one this is a no-op.
    throw_if_stop_requested();
    system->process(*event);
    if (std::holds_alternative<RgbdFrame>(*event)) {
      ++frames;
      if (progress) progress(frames);
    }
  }
  system->finish();
  const double wall_s = seconds_since(start);
  summary = summarize(*system, stream.description(), wall_s);
  return system;
}

}  // namespace wifislam::slam::system
