#pragma once
// ORB-SLAM2's place recognition and loop detection (Mur-Artal & Tardós 2017; paper, "ORB-SLAM")
// as a front end of the shared pipeline, with the paper's per-cluster Wi-Fi dictionaries.
//
// For each new keyframe (select):
//   1. its BoW vector and direct index in the vocabulary (slam/bow/vocabulary_tree.hpp);
//   2. local mapping: the previous keyframe (role predecessor) and the best covisible keyframes
//      of the previous keyframe (role neighbour, OrbslamOptions::local_keyframes): where ORB-SLAM
//      matches a keyframe against its local map;
//   3. loop detection (LoopClosing::DetectLoop), unless fewer than `keyframes_between_loops`
//      keyframes have passed since the last accepted loop closure or exist at all:
//        - connected keyframes: its covisible ones known so far (the tracking edge) and the local
//          keyframes of step 2. ORB-SLAM detects loops after local mapping has linked the
//          keyframe into the covisibility graph; here detection runs before this keyframe's
//          verification, and its local keyframes are what that linking would find;
//        - minScore: the lowest L1 score between the keyframe and a connected keyframe (no
//          connected keyframe, e.g. tracking lost: no detection, as ORB-SLAM relocalises then);
//        - DetectLoopCandidates over the inverted index (slam/bow/keyframe_database.hpp), groups
//          of `covisibility_group_size` best covisible neighbours; neither the connected
//          keyframes nor those too recent to be a loop closure by the pipeline's loop rule are
//          candidates (in ORB-SLAM2 the recent ones share map points, so they are connected);
//        - temporal consistency over `loop_consistency` keyframes (slam/bow/loop_consistency.hpp);
//        - the SearchByBoW gate (`bow_min_matches`, slam/bow/bow_feature_matcher.hpp);
//      what passes is verified (role long_term; `min_matches` = the Sim3 RANSAC inliers).
//   4. the keyframe enters the inverted index after its own query, as in ORB-SLAM2.
// Acceptance keeps every ordinary visual edge and the loop hypothesis with most inliers
// (ORB-SLAM2 closes one loop per keyframe); the pipeline then optimises the pose graph (ORB-SLAM2
// corrects the loop and optimises the essential graph).
// Covisibility (after_verification): every accepted visual or loop edge of the keyframe with at
// least `covisibility_min_weight` inliers (covisibility_graph.hpp).
//
// With a Wi-Fi module (paper, "ORB-SLAM", "Wi-Fi Augmentation"):
//   - one inverted index per Wi-Fi cluster; a keyframe enters the index of the cluster cluster
//     management puts it in (it hears the module's join and found events);
//   - a query looks up only the indexes of the keyframe's similar clusters;
//   - cluster management: the keyframe joins a similar cluster it has a visual edge or a covisible
//     keyframe in (its covisible keyframes are its accepted edges of at least 15 inliers, a subset
//     of its visual edges, so the module's default rule is the paper's), else founds one with its
//     own index.
//   A keyframe signed before the first scan has no Wi-Fi information: it queries every index and
//   enters an index of keyframes without a cluster, which every query also reads.

#include <chrono>
#include <map>
#include <memory>
#include <vector>

#include "slam/bow/bow_feature_matcher.hpp"
#include "slam/bow/keyframe_database.hpp"
#include "slam/bow/loop_consistency.hpp"
#include "slam/bow/vocabulary_tree.hpp"
#include "slam/frontend/front_end.hpp"
#include "slam/frontend/orbslam/covisibility_graph.hpp"
#include "slam/frontend/orbslam/orbslam_options.hpp"

namespace wifislam::slam::frontend::orbslam {

/// What loop detection did for one keyframe (a row of orbslam_queries.csv).
struct OrbslamQueryRecord {
  graph::KeyframeId keyframe = -1;
  bool detection_ran = false;
  int databases_searched = 0;          // inverted indexes read (vanilla: 1)
  std::size_t keyframes_searched = 0;  // keyframes in them
  std::size_t postings_read = 0;       // inverted-index entries read
  double min_score = 0.0;
  int candidates = 0;  // DetectLoopCandidates' groups
  int consistent = 0;  // after temporal consistency
  int bow_passed = 0;  // after the SearchByBoW gate: verified
  graph::KeyframeId accepted_loop = -1;
  wifi::ClusterId cluster = -1;  // the Wi-Fi cluster the keyframe joined (-1: none / vanilla)
  double query_ms = 0.0;         // steps 1 and 3 (BoW transform, detection, BoW matching)
};

class OrbslamFrontEnd final : public FrontEnd {
 public:
  explicit OrbslamFrontEnd(const OrbslamOptions& options);

  std::vector<Candidate> select(const SelectionQuery& query) override;

  const OrbslamOptions& options() const { return options_; }
  const bow::VocabularyTree& vocabulary() const { return *vocabulary_; }
  const orbslam::CovisibilityGraph& covisibility() const { return covisibility_; }
  const std::vector<OrbslamQueryRecord>& records() const { return records_; }
  /// The inverted index of every keyframe (vanilla), of a Wi-Fi cluster, or of the keyframes
  /// without a cluster (cluster -1).
  const bow::KeyframeDatabase& database() const { return all_; }
  const std::map<wifi::ClusterId, bow::KeyframeDatabase>& cluster_databases() const {
    return by_cluster_;
  }
  const bow::BowVector& bow_of(graph::KeyframeId keyframe) const { return bow_.at(keyframe); }

 protected:
  void on_wifi_attached() override;
  void after_verification(const VerificationReport& report) override;
  void write_own_outputs(const std::filesystem::path& run_dir) const override;
  nlohmann::json own_summary() const override;

 private:
  std::vector<Candidate> detect_loop(const SelectionQuery& query,
                                     const std::vector<graph::KeyframeId>& connected,
                                     OrbslamQueryRecord& record);
  std::vector<const bow::KeyframeDatabase*> databases_to_search() const;

  OrbslamOptions options_;
  std::shared_ptr<const bow::VocabularyTree> vocabulary_;
  int direct_index_levels_up_ = 1;
  orbslam::CovisibilityGraph covisibility_;
  bow::LoopConsistency consistency_;
  bow::KeyframeDatabase all_;                                    // vanilla
  std::map<wifi::ClusterId, bow::KeyframeDatabase> by_cluster_;  // Wi-Fi; -1: without a cluster
  std::map<graph::KeyframeId, bow::BowVector> bow_;
  std::map<graph::KeyframeId, bow::BowKeyframe> bow_keyframes_;
  const graph::PoseGraph* graph_ = nullptr;
  graph::KeyframeId last_loop_ = -1;
  std::vector<OrbslamQueryRecord> records_;
};

}  // namespace wifislam::slam::frontend::orbslam
