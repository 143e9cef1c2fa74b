#pragma once
// Options of the Wi-Fi module (paper, "General approach"; docs/frontends.md). Each
// field says what it trades off; the flat `--set` keys are listed in slam_options.cpp.

namespace wifislam::slam::wifi {

struct WifiOptions {
  /// Run the front end's Wi-Fi variant (clustering, bounded loop-closure search, cluster
  /// management). Needs Wi-Fi scans in the stream.
  bool enabled = false;
  /// Two signatures are "similar" when their cosine similarity is at least this. The Wi-Fi
  /// counterpart of `min_matches`: higher -> smaller clusters, fewer candidates, fewer false loop
  /// closures but more missed ones. Default 0.9, chosen from the similarity-vs-distance curves of
  /// the shipped scenes (pause-to-pause pairs; bench/wifi/wifi_similarity_curve): at 0.9, 92-100 %
  /// of pause pairs less than 4 m apart are similar and 0-6 % of pairs 12 m or more apart are, in
  /// every walled scene (c_hall, b_hall, j_hall, aliasing_ladder). In the open a_hall every pair
  /// scores > 0.94, so there the module cannot separate places (as the paper's A Hall, with few
  /// walls, suggests) and the Wi-Fi variant behaves much like vanilla.
  double similarity = 0.9;
  /// RSSI enters the cosine as max(0, rssi_dbm - floor_dbm); an AP not heard counts 0.
  double floor_dbm = -100.0;
  /// Scans belong to one pause while the receiver stands still: a new pause starts when the time
  /// from one scan's end to the next one's start exceeds this (scans of one pause follow each
  /// other every few seconds; between pauses the robot drives 3-4 m, several seconds more) ...
  double pause_gap_s = 3.0;
  /// ... or, when wheel odometry is in the stream, when the base moved more than this since the
  /// pause's first scan (so scanning while moving gives one signature per scan, not one per run).
  double pause_motion_m = 0.05;
};

}  // namespace wifislam::slam::wifi
