#include "slam/wifi/wifi_cluster_map.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"

namespace wifislam::slam::wifi {

WifiClusterMap::WifiClusterMap(double similarity_threshold, double floor_dbm)
    : threshold_(similarity_threshold), representatives_(floor_dbm) {}

std::vector<SimilarCluster> WifiClusterMap::similar_clusters(const WifiSignature& signature) const {
  const Eigen::VectorXd similarity = representatives_.similarities(signature);
  std::vector<SimilarCluster> out;
  for (Eigen::Index i = 0; i < similarity.size(); ++i) {
    if (similarity(i) >= threshold_) out.push_back({static_cast<ClusterId>(i), similarity(i)});
  }
  std::stable_sort(out.begin(), out.end(), [](const SimilarCluster& a, const SimilarCluster& b) {
    return a.similarity > b.similarity;
  });
  return out;
}

ClusterId WifiClusterMap::cluster_of(graph::KeyframeId keyframe) const {
  if (keyframe < 0 || static_cast<std::size_t>(keyframe) >= cluster_of_keyframe_.size()) return -1;
  return cluster_of_keyframe_[static_cast<std::size_t>(keyframe)];
}

ClusterId WifiClusterMap::assign(graph::KeyframeId keyframe,
                                 std::shared_ptr<const WifiSignature> signature,
                                 const std::vector<SimilarCluster>& similar,
                                 const std::vector<graph::KeyframeId>& visually_connected) {
  if (keyframe < static_cast<graph::KeyframeId>(cluster_of_keyframe_.size())) {
    throw InvalidInputError(
        fmt::format("Wi-Fi cluster management: keyframe {} assigned out of order", keyframe));
  }
  cluster_of_keyframe_.resize(static_cast<std::size_t>(keyframe) + 1, -1);
  if (!signature) return -1;

  ClusterId joined = -1;
  for (const SimilarCluster& candidate : similar) {  // most similar first
    const bool has_edge_into =
        std::any_of(visually_connected.begin(), visually_connected.end(),
                    [&](graph::KeyframeId k) { return cluster_of(k) == candidate.cluster; });
    if (has_edge_into) {
      joined = candidate.cluster;
      break;
    }
  }
  if (joined < 0) {
    joined = static_cast<ClusterId>(clusters_.size());
    clusters_.push_back({joined, keyframe, signature, {}});
    representatives_.add(*signature);
  }
  clusters_[static_cast<std::size_t>(joined)].keyframes.push_back(keyframe);
  cluster_of_keyframe_[static_cast<std::size_t>(keyframe)] = joined;
  return joined;
}

std::string WifiClusterMap::to_csv() const {
  std::string out = "cluster_id,founder_keyframe,keyframes,representative_signature\n";
  for (const WifiCluster& c : clusters_) {
    out += fmt::format("{},{},{},{}\n", c.id, c.founder, fmt::join(c.keyframes, " "),
                       c.representative->to_text());
  }
  return out;
}

}  // namespace wifislam::slam::wifi
