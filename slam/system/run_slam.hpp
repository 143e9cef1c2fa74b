#pragma once
// Runs the pipeline over a whole sensor stream.

#include <functional>
#include <memory>

#include "core/sensor_stream.hpp"
#include "slam/system/run_summary.hpp"
#include "slam/system/slam_system.hpp"

namespace wifislam::slam::system {

/// Called after each frame with the number of frames processed (progress display).
using FrameProgress = std::function<void(std::int64_t frames)>;

/// Feeds every event of `stream` to a new SlamSystem, runs the final optimisation and returns
/// the finished system; `summary` receives the run summary. With `features`, every frame's
/// features come from that store (SlamSystem::use_feature_store).
std::unique_ptr<SlamSystem> run_slam(SensorStream& stream, const SlamOptions& options,
                                     RunSummary& summary, const FrameProgress& progress = {},
                                     const feature::FeatureStore* features = nullptr);

}  // namespace wifislam::slam::system
