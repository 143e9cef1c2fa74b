#pragma once
// wifi_clusters.csv of a Wi-Fi run folder:
//   cluster_id,founder_keyframe,keyframes,representative_signature
// keyframes: space-separated keyframe ids; representative_signature: ';'-separated `ap=rssi_dbm`
// pairs (ap = MAC with the last nibble zeroed, e.g. 02:1a:11:00:00:30=-61.5).

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wifislam::eval {

struct WifiCluster {
  std::int64_t id = -1;
  std::int64_t founder_keyframe = -1;
  std::vector<std::int64_t> keyframes;
  std::vector<std::pair<std::string, double>> representative_signature;  // ap -> rssi_dbm
};

/// Throws IoError / ParseError("file:line", column, ...) naming what is wrong.
std::vector<WifiCluster> read_wifi_clusters_csv(const std::filesystem::path& path);

}  // namespace wifislam::eval
