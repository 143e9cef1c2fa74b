#include "slam/wifi/pause_signature_tracker.hpp"

namespace wifislam::slam::wifi {

void PauseSignatureTracker::observe_odometry(const OdometryReading& reading) {
  base_position_m_ = reading.base_in_odom.translation().head<2>();
}

void PauseSignatureTracker::observe_scan(const WifiScan& scan) {
  bool new_pause = pause_scans_.empty();
  if (!new_pause) {
    const double gap_s =
        static_cast<double>(scan.start_time.ns - pause_scans_.back().end_time.ns) * 1e-9;
    new_pause = gap_s > options_.pause_gap_s;
  }
  if (!new_pause && base_position_m_ && pause_position_m_) {
    new_pause = (*base_position_m_ - *pause_position_m_).norm() > options_.pause_motion_m;
  }
  if (new_pause) {
    pause_scans_.clear();
    pause_position_m_ = base_position_m_;
    ++pause_count_;
  }
  pause_scans_.push_back(scan);
  current_ = std::make_shared<const WifiSignature>(aggregate_scans(pause_scans_));
}

}  // namespace wifislam::slam::wifi
