#pragma once
// RGBD-SLAM augmented with Wi-Fi (paper, "RGBD SLAM", "Wi-Fi Augmentation"). Predecessors and
// geodesic neighbours stay as they are (motion estimation); the random earlier keyframes (group
// (c), long-term loop closure) are drawn only from keyframes of clusters whose representative
// signature is similar to the new keyframe's (bounding loop-closure search). After verification
// the keyframe joins a cluster or founds one (cluster management).
//
// Choices where the paper is silent, all documented in WifiOptions:
// - The number of long-term candidates is WifiOptions::sampled_candidates (default: the same as
//   vanilla's `min_sampled_candidates`), drawn uniformly from the bounded pool.
// - The pool leaves out the last `loop_min_keyframe_gap` keyframes: a match with one of them is
//   an ordinary visual edge, not a loop closure, and predecessors/neighbours already cover them.
// - A keyframe made before the first scan has no Wi-Fi information: its long-term candidates are
//   drawn as in vanilla RGBD-SLAM, and it joins no cluster.

#include <memory>
#include <optional>

#include "slam/loop/rgbdslam_candidate_selector.hpp"
#include "slam/util/instrumentation.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"
#include "slam/wifi/wifi_cluster_map.hpp"
#include "slam/wifi/wifi_options.hpp"

namespace wifislam::slam {

namespace module {
inline constexpr const char* kWifiClustering = "wifi_clustering";
inline constexpr const char* kWifiClusterManagement = "wifi_cluster_management";
}  // namespace module
namespace counter {
inline constexpr const char* kWifiSimilarityComparisons = "wifi_similarity_comparisons";
inline constexpr const char* kWifiUnsignedKeyframes = "wifi_keyframes_without_signature";
inline constexpr const char* kWifiBoundedPool = "wifi_bounded_pool_keyframes";
}  // namespace counter

class WifiRgbdslamCandidateSelector : public RgbdslamCandidateSelector {
 public:
  WifiRgbdslamCandidateSelector(const RgbdslamOptions& rgbdslam, const WifiOptions& wifi,
                                int loop_min_keyframe_gap, std::uint64_t seed,
                                Instrumentation& instrumentation);

  std::string name() const override { return "rgbdslam+wifi"; }
  void observe_wifi_scan(const WifiScan& scan) override;
  void observe_odometry(const OdometryReading& reading) override;
  void on_verified(const VerificationReport& report) override;
  void write_outputs(const std::filesystem::path& run_dir) const override;
  nlohmann::json summary() const override;

  const WifiClusterMap& clusters() const { return clusters_; }

 protected:
  std::vector<KeyframeId> long_term_candidates(const SelectionQuery& query,
                                               const std::vector<KeyframeId>& eligible) override;

 private:
  struct PendingKeyframe {
    KeyframeId keyframe = -1;
    std::shared_ptr<const WifiSignature> signature;
    std::vector<SimilarCluster> similar;
  };

  WifiOptions wifi_;
  int loop_min_keyframe_gap_;
  Instrumentation* instrumentation_;
  PauseSignatureTracker pauses_;
  WifiClusterMap clusters_;
  std::optional<PendingKeyframe> pending_;
  Rng wifi_rng_;
};

}  // namespace wifislam::slam
