#include "slam/loop/wifi_rgbdslam_candidate_selector.hpp"

#include <stdexcept>

#include "core/atomic_file.hpp"

namespace wifislam::slam {

WifiRgbdslamCandidateSelector::WifiRgbdslamCandidateSelector(const RgbdslamOptions& rgbdslam,
                                                             const WifiOptions& wifi,
                                                             int loop_min_keyframe_gap,
                                                             std::uint64_t seed,
                                                             Instrumentation& instrumentation)
    : RgbdslamCandidateSelector(rgbdslam, seed),
      wifi_(wifi),
      loop_min_keyframe_gap_(loop_min_keyframe_gap),
      instrumentation_(&instrumentation),
      pauses_(wifi),
      clusters_(wifi.similarity, wifi.floor_dbm),
      wifi_rng_(Rng::stream(seed, "slam/wifi/candidates")) {}

void WifiRgbdslamCandidateSelector::observe_wifi_scan(const WifiScan& scan) {
  // Signature aggregation is part of the Wi-Fi overhead; it is booked with clustering.
  ScopedTimer timer(*instrumentation_, module::kWifiClustering);
  pauses_.observe_scan(scan);
}

void WifiRgbdslamCandidateSelector::observe_odometry(const OdometryReading& reading) {
  pauses_.observe_odometry(reading);
}

std::vector<KeyframeId> WifiRgbdslamCandidateSelector::long_term_candidates(
    const SelectionQuery& query, const std::vector<KeyframeId>& eligible) {
  PendingKeyframe pending{query.keyframe, pauses_.current(), {}};
  if (!pending.signature) {
    instrumentation_->count(counter::kWifiUnsignedKeyframes);
    pending_ = std::move(pending);
    return RgbdslamCandidateSelector::long_term_candidates(query, eligible);
  }

  std::vector<KeyframeId> pool;
  {
    ScopedTimer timer(*instrumentation_, module::kWifiClustering);
    pending.similar = clusters_.similar_clusters(*pending.signature);
    instrumentation_->count(counter::kWifiSimilarityComparisons,
                            static_cast<std::int64_t>(clusters_.clusters().size()));
    // Bounding: eligible keyframes (ascending) that belong to a similar cluster and are old
    // enough for a match to be a loop closure.
    std::vector<std::uint8_t> similar(clusters_.clusters().size(), 0);
    for (const SimilarCluster& s : pending.similar)
      similar[static_cast<std::size_t>(s.cluster)] = 1;
    for (KeyframeId id : eligible) {
      if (query.keyframe - id < loop_min_keyframe_gap_) break;
      const ClusterId c = clusters_.cluster_of(id);
      if (c >= 0 && similar[static_cast<std::size_t>(c)]) pool.push_back(id);
    }
  }
  instrumentation_->count(counter::kWifiBoundedPool, static_cast<std::int64_t>(pool.size()));
  pending_ = std::move(pending);
  if (wifi_.sampled_candidates <= 0) return pool;
  return sample_without_replacement(pool, wifi_.sampled_candidates, wifi_rng_);
}

void WifiRgbdslamCandidateSelector::on_verified(const VerificationReport& report) {
  ScopedTimer timer(*instrumentation_, module::kWifiClusterManagement);
  if (!pending_ || pending_->keyframe != report.keyframe) {
    throw std::logic_error("Wi-Fi cluster management: keyframe verified without selection");
  }
  clusters_.assign(report.keyframe, pending_->signature, pending_->similar,
                   report.visually_connected());
  pending_.reset();
}

void WifiRgbdslamCandidateSelector::write_outputs(const std::filesystem::path& run_dir) const {
  write_file_atomic(run_dir / "wifi_clusters.csv", clusters_.to_csv());
}

nlohmann::json WifiRgbdslamCandidateSelector::summary() const {
  std::size_t clustered = 0;
  for (const WifiCluster& c : clusters_.clusters()) clustered += c.keyframes.size();
  return {{"wifi_clusters", clusters_.clusters().size()},
          {"wifi_clustered_keyframes", clustered},
          {"wifi_pauses", pauses_.pause_count()},
          {"wifi_similarity", wifi_.similarity},
          {"wifi_floor_dbm", wifi_.floor_dbm},
          {"wifi_sampled_candidates", wifi_.sampled_candidates}};
}

}  // namespace wifislam::slam
