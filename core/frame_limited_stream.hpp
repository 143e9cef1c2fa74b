#pragma once
// A SensorStream that ends after a number of frames: `--max-frames` on a dataset folder, so a
// long dataset can be tried on its first minutes as a scene can. Events after the last frame
// (scans, odometry) are dropped with it.

#include <cstdint>
#include <memory>
#include <utility>

#include "core/sensor_stream.hpp"

namespace wifislam {

class FrameLimitedStream final : public SensorStream {
 public:
  FrameLimitedStream(std::unique_ptr<SensorStream> inner, std::int64_t max_frames)
      : inner_(std::move(inner)), max_frames_(max_frames) {}

  std::optional<SensorEvent> next() override {
    if (frames_ >= max_frames_) return std::nullopt;
    std::optional<SensorEvent> event = inner_->next();
    if (event && std::holds_alternative<RgbdFrame>(*event)) ++frames_;
    return event;
  }
  const CameraIntrinsics& intrinsics() const override { return inner_->intrinsics(); }
  Pose camera_in_base() const override { return inner_->camera_in_base(); }
  bool has_wifi() const override { return inner_->has_wifi(); }
  bool has_odometry() const override { return inner_->has_odometry(); }
  std::string description() const override {
    return inner_->description() + " (first " + std::to_string(max_frames_) + " frames)";
  }

 private:
  std::unique_ptr<SensorStream> inner_;
  std::int64_t max_frames_;
  std::int64_t frames_ = 0;
};

}  // namespace wifislam
