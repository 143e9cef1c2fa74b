#pragma once
// Wi-Fi and visual association (paper, "General approach"): the robot pauses every few metres to
// scan, and every frame that follows carries the signature of that pause until the next one.
// This tracker sees the scans (and odometry) in stream order, groups consecutive scans into
// pauses, and answers "which signature does a frame at this point of the stream carry".
//
// A pause is not announced in the stream, so it is recognised: scans follow each other closely
// while the receiver stands still (WifiOptions::pause_gap_s) and, when wheel odometry is present,
// the base has not moved (WifiOptions::pause_motion_m). While a pause is in progress its signature
// is the aggregate of the scans seen so far: a keyframe made during the pause gets the place's
// signature as far as it is known then, and never a later scan's (the stream stays causal).

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/sensor_stream.hpp"
#include "core/wifi_scan.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::slam::wifi {

class PauseSignatureTracker {
 public:
  explicit PauseSignatureTracker(const WifiOptions& options) : options_(options) {}

  void observe_odometry(const OdometryReading& reading);
  void observe_scan(const WifiScan& scan);

  /// The signature frames carry now: the latest pause's; null before the first scan ("no Wi-Fi
  /// information"). Shared so keyframes can keep it cheaply.
  std::shared_ptr<const WifiSignature> current() const { return current_; }
  /// Pauses recognised so far.
  int pause_count() const { return pause_count_; }

 private:
  WifiOptions options_;
  std::optional<Eigen::Vector2d> base_position_m_;   // latest odometry
  std::optional<Eigen::Vector2d> pause_position_m_;  // odometry at the pause's first scan
  std::vector<WifiScan> pause_scans_;
  std::shared_ptr<const WifiSignature> current_;
  int pause_count_ = 0;
};

}  // namespace wifislam::slam::wifi
