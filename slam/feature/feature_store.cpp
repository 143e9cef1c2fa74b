#include "slam/feature/feature_store.hpp"
#include "core/wall_clock.hpp"

#include <chrono>

namespace wifislam::slam::feature {

FeatureStore::FeatureStore(const FeatureOptions& options, const CameraIntrinsics& intrinsics)
    : extractor_(options, intrinsics) {}

void FeatureStore::add(const RgbdFrame& frame) {
  const auto start = std::chrono::steady_clock::now();
  auto features = std::make_shared<const FrameFeatures>(extractor_.extract(frame));
  const double seconds = seconds_since(start);
  std::lock_guard lock(mutex_);
  entries_.emplace(frame.index, Entry{std::move(features), seconds});
}

const FeatureStore::Entry* FeatureStore::find(std::int64_t frame_index) const {
  const auto it = entries_.find(frame_index);
  return it == entries_.end() ? nullptr : &it->second;
}

std::size_t FeatureStore::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace wifislam::slam::feature
