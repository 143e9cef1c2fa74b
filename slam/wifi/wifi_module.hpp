#pragma once
// The Wi-Fi module of the paper ("General approach"; docs/frontends.md): one object
// that a front end holds. Nothing in it knows which front end holds it; a front end calls it at
// the paper's points, in this order for each new place (an RGBD-SLAM keyframe, an RTAB-Map node,
// an ORB-SLAM keyframe: all called "keyframe" here, ids growing):
//
//   observe_scan / observe_odometry   every scan and odometry reading, in stream order
//   sign(k)                           Wi-Fi clustering: k carries the last pause's signature;
//                                     the clusters similar to it are found (one mat-vec product)
//   bound(ids), in_similar_cluster,   bounding: keep what lies in a similar cluster of k
//   similar_cluster_keyframes()         (and, for memory-managing front ends, immunisation and
//                                     retrieval ask the same question)
//   assign(k, visually_connected)     cluster management, after verification: join the most
//                                     similar similar cluster k has a visual edge (or covisible
//                                     keyframe) into, or found a new one
//
// Listeners hear every cluster founded and every keyframe that joins one (per-cluster indexes,
// e.g. an ORB-SLAM-style word index per cluster).
//
// A keyframe signed before the first scan has no signature ("no Wi-Fi information"): it has no
// similar clusters, bound() leaves a candidate set unchanged for it (Wi-Fi cannot say where it
// is), and it joins no cluster. Whether a front end then searches as its vanilla self is the
// front end's choice (has_signature() tells it).

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/sensor_stream.hpp"
#include "core/wifi_scan.hpp"
#include "slam/graph/pose_graph.hpp"
#include "slam/util/instrumentation.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"
#include "slam/wifi/wifi_cluster_map.hpp"
#include "slam/wifi/wifi_options.hpp"

namespace wifislam::slam::wifi {

/// A cluster was founded (by `keyframe`, which is also its first member) or `keyframe` joined it.
struct ClusterEvent {
  enum class Kind { kFounded, kJoined };
  Kind kind = Kind::kFounded;
  ClusterId cluster = -1;
  graph::KeyframeId keyframe = -1;
};
using ClusterListener = std::function<void(const ClusterEvent&)>;

class WifiModule {
 public:
  /// Time goes to `instrumentation` under wifi_clustering / wifi_cluster_management, work to the
  /// wifi_* counters (core/run_format.hpp).
  WifiModule(const WifiOptions& options, util::Instrumentation& instrumentation);

  const WifiOptions& options() const { return options_; }

  // --- Clustering -------------------------------------------------------------------------
  void observe_scan(const WifiScan& scan);
  void observe_odometry(const OdometryReading& reading);

  /// Gives `keyframe` the signature frames carry now and finds its similar clusters; it becomes
  /// the current keyframe that bound() and the queries below speak of. Ids must grow
  /// (InvalidInputError otherwise); signing the current keyframe again is a no-op.
  void sign(graph::KeyframeId keyframe);
  /// The current keyframe (-1 before the first sign()).
  graph::KeyframeId current() const { return current_; }
  /// Whether the current keyframe has a signature.
  bool has_signature() const { return signature_of(current_) != nullptr; }
  /// The signature `keyframe` was signed with; null when unsigned or signed before any scan.
  std::shared_ptr<const WifiSignature> signature_of(graph::KeyframeId keyframe) const;
  /// The current keyframe's similar clusters, most similar first.
  const std::vector<SimilarCluster>& similar_clusters() const { return similar_; }

  // --- Bounding ---------------------------------------------------------------------------
  /// The entries of `keyframes` (order kept) that belong to a similar cluster of the current
  /// keyframe; all of them when it has no signature.
  std::vector<graph::KeyframeId> bound(const std::vector<graph::KeyframeId>& keyframes) const;
  /// Whether `keyframe` belongs to a similar cluster of the current keyframe now (immunisation).
  bool in_similar_cluster(graph::KeyframeId keyframe) const;
  /// Every keyframe of the current keyframe's similar clusters, ascending (retrieval).
  std::vector<graph::KeyframeId> similar_cluster_keyframes() const;

  // --- Cluster management -----------------------------------------------------------------
  /// Assigns the current keyframe (which must be `keyframe`) given the keyframes it is visually
  /// connected to. Returns the cluster joined or founded, -1 without a signature.
  ClusterId assign(graph::KeyframeId keyframe,
                   const std::vector<graph::KeyframeId>& visually_connected);
  void subscribe(ClusterListener listener) { listeners_.push_back(std::move(listener)); }

  // --- State and outputs ------------------------------------------------------------------
  const WifiClusterMap& clusters() const { return clusters_; }
  /// -1 when `keyframe` is in no cluster.
  ClusterId cluster_of(graph::KeyframeId keyframe) const { return clusters_.cluster_of(keyframe); }
  int pause_count() const { return pauses_.pause_count(); }
  /// wifi_clusters.csv into `run_dir`.
  void write_outputs(const std::filesystem::path& run_dir) const;
  /// The module's part of run.json.
  nlohmann::json summary() const;

 private:
  WifiOptions options_;
  util::Instrumentation* instrumentation_;
  PauseSignatureTracker pauses_;
  WifiClusterMap clusters_;
  std::vector<std::shared_ptr<const WifiSignature>> signature_of_keyframe_;
  graph::KeyframeId current_ = -1;
  bool current_assigned_ = false;
  std::vector<SimilarCluster> similar_;
  std::vector<std::uint8_t> cluster_is_similar_;  // by cluster id, for the current keyframe
  std::vector<ClusterListener> listeners_;
};

}  // namespace wifislam::slam::wifi
