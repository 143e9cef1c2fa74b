#pragma once
// The radio level of a study case: what the robot's Wi-Fi can tell apart along its route, with
// no rendering and no SLAM. The case's scene is simulated in memory (world, access points, radio,
// the robot's pauses and scans, exactly as a dataset would have them); each pause's signature is
// formed as the SLAM's Wi-Fi module forms it (slam/wifi/pause_signature_tracker.hpp), at the
// robot's true position, and every pair of pauses is scored by cosine similarity against their
// true distance.
//
// Metrics (the similarity threshold is the SLAM's wifi_similarity):
//  - resolution_m: the distance at which the median similarity of pause pairs falls below the
//    threshold. Pairs are binned by distance (1 m bins, at least kMinPairsPerBin pairs); the
//    crossing is interpolated linearly between the centres of the last bin at or above the
//    threshold and the first below it. Smaller is better: places that far apart are told apart.
//    Absent (nullopt) when no bin falls below it (the route's places all look alike).
//  - near_similar_share: pairs closer than 4 m that count as similar (higher is better: the
//    same place is recognised);
//  - far_similar_share: pairs farther than 12 m that count as similar (lower is better: the
//    Wi-Fi would let a far look-alike through, the false loop closure it exists to prevent);
//  - clusters: Wi-Fi clusters formed along the route by the SLAM's cluster management
//    (slam/wifi/wifi_cluster_map.hpp), each pause a keyframe whose visual edge is to the previous
//    pause, as the odometry chain gives one;
//  - aps_heard_per_pause: mean number of access points in a pause's signature.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sim/scene/scene.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::study {

inline constexpr int kMinPairsPerBin = 3;

struct PauseSample {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // true position at the pause's end
  slam::WifiSignature signature;
};

/// The route's pauses with their signatures, simulated in memory (no images).
std::vector<PauseSample> simulate_pauses(const Scene& scene, const slam::WifiOptions& wifi);

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
                                 const slam::WifiOptions& wifi);

}  // namespace wifislam::study
