#include "slam/wifi/wifi_module.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/run_format.hpp"

namespace wifislam::slam::wifi {

WifiModule::WifiModule(const WifiOptions& options, util::Instrumentation& instrumentation)
    : options_(options),
      instrumentation_(&instrumentation),
      pauses_(options),
      clusters_(options.similarity, options.floor_dbm) {}

void WifiModule::observe_scan(const WifiScan& scan) {
  // Signature aggregation is part of the Wi-Fi overhead; it is booked with clustering.
  util::ScopedTimer timer(*instrumentation_, module::kWifiClustering);
  pauses_.observe_scan(scan);
}

void WifiModule::observe_odometry(const OdometryReading& reading) {
  pauses_.observe_odometry(reading);
}

void WifiModule::sign(graph::KeyframeId keyframe) {
  if (keyframe == current_) return;
  if (keyframe < current_ || keyframe < 0) {
    throw InvalidInputError(fmt::format(
        "Wi-Fi module: keyframe {} signed after keyframe {} (ids must grow)", keyframe, current_));
  }
  util::ScopedTimer timer(*instrumentation_, module::kWifiClustering);
  current_ = keyframe;
  current_assigned_ = false;
  std::shared_ptr<const WifiSignature> signature = pauses_.current();
  signature_of_keyframe_.resize(static_cast<std::size_t>(keyframe) + 1);
  signature_of_keyframe_[static_cast<std::size_t>(keyframe)] = signature;
  similar_.clear();
  cluster_is_similar_.assign(clusters_.clusters().size(), 0);
  if (!signature) {
    instrumentation_->count(counter::kWifiUnsignedKeyframes);
    return;
  }
  similar_ = clusters_.similar_clusters(*signature);
  instrumentation_->count(counter::kWifiSimilarityComparisons,
                          static_cast<std::int64_t>(clusters_.clusters().size()));
  for (const SimilarCluster& s : similar_)
    cluster_is_similar_[static_cast<std::size_t>(s.cluster)] = 1;
}

std::shared_ptr<const WifiSignature> WifiModule::signature_of(graph::KeyframeId keyframe) const {
  if (keyframe < 0 || static_cast<std::size_t>(keyframe) >= signature_of_keyframe_.size()) {
    return nullptr;
  }
  return signature_of_keyframe_[static_cast<std::size_t>(keyframe)];
}

bool WifiModule::in_similar_cluster(graph::KeyframeId keyframe) const {
  const ClusterId c = clusters_.cluster_of(keyframe);
  return c >= 0 && static_cast<std::size_t>(c) < cluster_is_similar_.size() &&
         cluster_is_similar_[static_cast<std::size_t>(c)] != 0;
}

std::vector<graph::KeyframeId> WifiModule::bound(
    const std::vector<graph::KeyframeId>& keyframes) const {
  if (!has_signature()) return keyframes;
  util::ScopedTimer timer(*instrumentation_, module::kWifiClustering);
  std::vector<graph::KeyframeId> out;
  for (graph::KeyframeId k : keyframes) {
    if (in_similar_cluster(k)) out.push_back(k);
  }
  instrumentation_->count(counter::kWifiBoundedPool, static_cast<std::int64_t>(out.size()));
  return out;
}

std::vector<graph::KeyframeId> WifiModule::similar_cluster_keyframes() const {
  std::vector<graph::KeyframeId> out;
  for (const SimilarCluster& s : similar_) {
    const std::vector<graph::KeyframeId>& members =
        clusters_.clusters()[static_cast<std::size_t>(s.cluster)].keyframes;
    out.insert(out.end(), members.begin(), members.end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

ClusterId WifiModule::assign(graph::KeyframeId keyframe,
                             const std::vector<graph::KeyframeId>& visually_connected) {
  if (keyframe != current_ || current_assigned_) {
    throw std::logic_error(fmt::format(
        "Wi-Fi cluster management: keyframe {} assigned, but the signed keyframe is {}{}", keyframe,
        current_, current_assigned_ ? " (already assigned)" : ""));
  }
  util::ScopedTimer timer(*instrumentation_, module::kWifiClusterManagement);
  current_assigned_ = true;
  const std::size_t clusters_before = clusters_.clusters().size();
  const ClusterId cluster =
      clusters_.assign(keyframe, signature_of(keyframe), similar_, visually_connected);
  if (cluster < 0) return cluster;
  const bool founded = clusters_.clusters().size() > clusters_before;
  instrumentation_->count(founded ? counter::kWifiClustersFounded : counter::kWifiClusterJoins);
  const ClusterEvent event{founded ? ClusterEvent::Kind::kFounded : ClusterEvent::Kind::kJoined,
                           cluster, keyframe};
  for (const ClusterListener& listener : listeners_) listener(event);
  return cluster;
}

void WifiModule::write_outputs(const std::filesystem::path& run_dir) const {
  write_file_atomic(run_dir / run_folder::kWifiClusters, clusters_.to_csv());
}

nlohmann::json WifiModule::summary() const {
  std::size_t clustered = 0;
  for (const WifiCluster& c : clusters_.clusters()) clustered += c.keyframes.size();
  return {{"wifi_clusters", clusters_.clusters().size()},
          {"wifi_clustered_keyframes", clustered},
          {"wifi_pauses", pauses_.pause_count()},
          {"wifi_similarity", options_.similarity},
          {"wifi_floor_dbm", options_.floor_dbm}};
}

}  // namespace wifislam::slam::wifi
