#pragma once
// The radio level of a study case: what the robot's Wi-Fi can tell apart along its route, with
// no rendering and no SLAM. The case's scene is simulated in memory (world, access points, radio,
// the robot's pauses and scans, exactly as a dataset would have them); each pause's signature is
// formed as the SLAM's Wi-Fi module forms it (slam/wifi/pause_signature_tracker.hpp), at the
// robot's true position, and every pair of pauses is scored by cosine similarity against their
// true distance.
//
// Metrics (the similarity threshold is the SLAM's wifi_similarity):
//  - resolution_m: the distance beyond which pause pairs stay told apart: pairs are binned by
//    distance (1 m bins, at least kMinPairsPerBin pairs), and the crossing is interpolated
//    linearly between the centres of the last bin whose median similarity is at or above the
//    threshold and the bin after it. Smaller is better. The last such bin, not the first below
//    the threshold, so that far look-alikes (mirrored corridors, co-linear APs) count against a
//    placement, and pairs that are dissimilar only because neither pause heard an AP do not
//    count for it. Absent (nullopt) when no bin is at or above the threshold (not even the
//    nearest places are recognised) or the farthest bin still is (places never look different).
//  - near_similar_share: pairs closer than 4 m that count as similar (higher is better: the
//    same place is recognised);
//  - far_similar_share: pairs farther than 12 m that count as similar (lower is better: the
//    Wi-Fi would let a far look-alike through, the false loop closure it exists to prevent);
//  - clusters: Wi-Fi clusters formed along the route by the SLAM's cluster management
//    (slam/wifi/wifi_cluster_map.hpp), each pause a keyframe whose visual edge is to the previous
//    pause, as the odometry chain gives one;
//  - aps_heard_per_pause: mean number of access points in a pause's signature.

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sim/site/site.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::study {

inline constexpr int kMinPairsPerBin = 3;

struct PauseSample {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // true position at the pause's end
  slam::wifi::WifiSignature signature;
};

/// The route's pauses with their signatures, simulated in memory on the site (no images).
/// `ap_keys`, when given, receives each access point's signature key in the site's AP order
/// (ids 0..n-1).
std::vector<PauseSample> simulate_pauses(
    std::shared_ptr<const sim::site::Site> site, const slam::wifi::WifiOptions& wifi,
    std::vector<slam::wifi::AccessPointKey>* ap_keys = nullptr);

struct RadioResolution {
  int pauses = 0;
  int pairs = 0;
  std::optional<double> resolution_m;
  double near_similar_share = 0.0;
  double far_similar_share = 0.0;
  int clusters = 0;
  double aps_heard_per_pause = 0.0;
};

RadioResolution radio_resolution(const std::vector<PauseSample>& pauses,
                                 const slam::wifi::WifiOptions& wifi);

}  // namespace wifislam::study
