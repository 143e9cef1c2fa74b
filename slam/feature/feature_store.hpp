#pragma once
// The features of every frame of one stream, extracted once and shared by the SLAM runs on it.
//
// Many runs on one dataset (a sweep of settings, vanilla and Wi-Fi) extract the same features
// from the same frames: extraction is a pure function of the frame and the FeatureOptions. A
// store is filled once (by any number of threads, one frame each), then read by any number of
// runs at once; a run given a store (SlamSystem::use_feature_store) takes each frame's features
// from it and never looks at the frame's images, so a replay of the stream needs none.
//
// Time: a run charges its timing.json's feature_extraction (and total) with the seconds the
// extraction took when the store was filled, so its times read as those of a run that extracted
// its own features; only its wall-clock is shorter.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

#include "core/camera_intrinsics.hpp"
#include "core/sensor_stream.hpp"
#include "slam/feature/frame_features.hpp"
#include "slam/feature/orb_feature_extractor.hpp"

namespace wifislam::slam::feature {

class FeatureStore {
 public:
  struct Entry {
    std::shared_ptr<const FrameFeatures> features;
    double extraction_s = 0.0;  // wall-clock of the extraction, as measured when it was made
  };

  FeatureStore(const FeatureOptions& options, const CameraIntrinsics& intrinsics);

  /// Extracts `frame`'s features and keeps them under frame.index (thread-safe; a frame added
  /// twice keeps its first entry).
  void add(const RgbdFrame& frame);

  /// The entry of a frame, or nullptr. Call once filling is over (no add() at the same time).
  const Entry* find(std::int64_t frame_index) const;
  std::size_t size() const;

  const FeatureOptions& options() const { return extractor_.options(); }

 private:
  OrbFeatureExtractor extractor_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, Entry> entries_;
};

}  // namespace wifislam::slam::feature
