#pragma once
// Wi-Fi clusters (paper, "General approach"): each cluster stands for a region of the building,
// has a representative signature (its founder's) and holds keyframes whose signatures are similar
// to it and that have a visual edge to another keyframe of the cluster.
//
// Wi-Fi clustering = similar_clusters(): cosine similarity of a keyframe's signature with every
// representative (one matrix-vector product), those >= WifiOptions::similarity, best first.
// Cluster management = assign(), after visual verification: join the most similar of the similar
// clusters that the keyframe now has a visual edge into; if there is none (no similar cluster, or
// similar ones without a visual edge), found a new cluster represented by this signature.

#include <memory>
#include <string>
#include <vector>

#include "slam/graph/pose_graph.hpp"
#include "slam/wifi/signature_similarity.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::slam::wifi {

using ClusterId = int;

struct SimilarCluster {
  ClusterId cluster = -1;
  double similarity = 0.0;
  friend bool operator==(const SimilarCluster&, const SimilarCluster&) = default;
};

struct WifiCluster {
  ClusterId id = -1;
  graph::KeyframeId founder = -1;
  std::shared_ptr<const WifiSignature> representative;
  std::vector<graph::KeyframeId> keyframes;  // ascending
};

class WifiClusterMap {
 public:
  WifiClusterMap(double similarity_threshold, double floor_dbm);

  /// Clusters with similarity >= threshold, most similar first (ties: lower id first).
  std::vector<SimilarCluster> similar_clusters(const WifiSignature& signature) const;

  /// Cluster management for a new keyframe (ids must grow). `similar` is what similar_clusters()
  /// returned for its signature; `visually_connected` the keyframes it has visual or loop edges
  /// with. Returns the cluster it joined or founded; a keyframe without a signature (null) joins
  /// none and -1 is returned.
  ClusterId assign(graph::KeyframeId keyframe, std::shared_ptr<const WifiSignature> signature,
                   const std::vector<SimilarCluster>& similar,
                   const std::vector<graph::KeyframeId>& visually_connected);

  /// -1 when the keyframe is in no cluster.
  ClusterId cluster_of(graph::KeyframeId keyframe) const;
  const std::vector<WifiCluster>& clusters() const { return clusters_; }

  /// wifi_clusters.csv: cluster_id,founder_keyframe,keyframes,representative_signature
  /// (keyframes space-separated, signature as WifiSignature::to_text()).
  std::string to_csv() const;

 private:
  double threshold_;
  SignatureSimilarityIndex representatives_;  // row i = cluster i
  std::vector<WifiCluster> clusters_;
  std::vector<ClusterId> cluster_of_keyframe_;
};

}  // namespace wifislam::slam::wifi
