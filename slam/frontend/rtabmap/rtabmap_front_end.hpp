#pragma once
// RTAB-Map's loop-closure detection and memory management (Labbé & Michaud 2013, 2019; paper,
// "RTAB-Map") as a front end of the shared pipeline, with the paper's Wi-Fi augmentation.
//
// Nodes. RTAB-Map makes a node at Rtabmap/DetectionRate (1 Hz) when the robot moved
// RGBD/LinearUpdate (0.1 m) or turned RGBD/AngularUpdate (0.1 rad); this front end gives the
// pipeline that schedule (keyframe_schedule), so a node is a keyframe (node id = keyframe id)
// made on it. The pipeline tracks each frame against the last node (with wheel odometry as the
// motion prior where tracking is lost); where that fails, its last tracked frame becomes a node
// off the schedule, as our tracking needs an anchor where RTAB-Map's frame-to-frame odometry
// would carry on (run.json: keyframes_after_tracking_loss).
//
// For each new node (select):
//   1. its strongest Kp/MaxFeatures ORB descriptors are quantised into the incremental
//      vocabulary (visual_vocabulary.hpp) and the node enters STM; the oldest STM node leaves
//      for WM (node_memory.hpp);
//   2. rehearsal: at Mem/RehearsalSimilarity or more with the previous node, the previous node
//      takes the new one's weight + 1. RTAB-Map then deletes the new node (the robot has not
//      moved); here the pipeline owns its graph nodes, so the new node stays, with weight 0;
//   3. retrieval: the graph neighbours of the last node's best hypothesis (margin up to the
//      prediction's reach, nearest first, STM left out) are immune to transfer this step, and up
//      to Rtabmap/MaxRetrieved of them come back from LTM (Rtabmap::process, "RETRIEVAL");
//      with Wi-Fi also every LTM node of a similar cluster, immune as long as its cluster is
//      similar ("Wi-Fi Cluster Retrieval");
//   4. likelihood of the node against every WM node (with Wi-Fi: only those of similar clusters,
//      "Bounding"), normalised, and the Bayes filter update (likelihood.hpp, bayes_filter.hpp);
//   5. candidates: the previous node (role predecessor: RTAB-Map links consecutive nodes), and
//      the best hypothesis when its posterior reaches Rtabmap/LoopThr (role long_term). The
//      pipeline verifies them (Vis/MinInliers = min_matches); acceptance keeps every ordinary
//      visual edge and the best loop closure, then drops loop closures that tear the graph
//      (RGBD/OptimizeMaxError; edge_acceptance.hpp).
//   6. proximity detection by space (RGBD/ProximityBySpace; Rtabmap::process, "Proximity
//      detections"): WM nodes within RGBD/LocalRadius of the node's estimated position and at most
//      RGBD/ProximityMaxGraphDepth links away (with Wi-Fi: only those of similar clusters, the
//      paper's bounding of verification), grouped into paths of consecutive ids; paths in order of
//      their highest likelihood (ties: the newer path), for up to RGBD/ProximityMaxPaths of them:
//      the path's most likely node when its likelihood is positive and it looks within
//      RGBD/ProximityAngle of the node's heading, else its nearest such node; verified (role
//      proximity) when not linked to the node yet and within RGBD/ProximityPathFilteringRadius.
//      Accepted proximity links are added beside the one global loop closure, as RTAB-Map adds
//      them, and face the same graph-consistency check.
// After verification (after_verification):
//   7. the node's processing time (cost model or wall clock) against Rtabmap/TimeThr: over it,
//      RTAB-Map's Memory::forget moves one node more than entered WM this step to LTM, lowest
//      weight and oldest first, keeping nodes immune this step, the best hypothesis, nodes linked
//      to an STM node (RTAB-Map: "links must not be in STM"), and with Wi-Fi every node of a
//      similar cluster ("Wi-Fi Immunization").
//
// What bounds WM when many nodes are immune: immunity lasts one step (retrieval) or while the
// cluster is similar to the current node (Wi-Fi). Transfers take only non-immune nodes, so WM is
// at most the immune nodes plus what the threshold allows of the rest; when the robot moves on,
// its old clusters stop being similar and become transferable again. Where Wi-Fi cannot tell
// places apart (the open a_hall twin: every signature pair is similar), every WM node stays
// immune and WM grows with the map, past the threshold, as the paper's A Hall times suggest.
// `wifi_max_immune` N caps immunity at the N nodes of the most similar clusters (default 0, no
// cap: the paper names none); WM is then at most N + what the threshold allows of the rest.
//
// Cost model calibration: see RtabmapCostModel (rtabmap_options.hpp). With its defaults a node
// costs ~3.6 ms + ~19 ms per 10^7 word comparisons + 1.7 ms per verification; quantisation
// dominates, so at 70 ms a map whose dictionary holds ~65 000 words (500 descriptors a node)
// starts transferring. Loop-closure time in RTAB-Map's sense (likelihood, posterior, the loop
// hypothesis' verification) is a few ms of it: that is the part Wi-Fi bounding shortens.

#include <chrono>
#include <deque>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "slam/frontend/front_end.hpp"
#include "slam/frontend/rtabmap/bayes_filter.hpp"
#include "slam/frontend/rtabmap/node_memory.hpp"
#include "slam/frontend/rtabmap/rtabmap_options.hpp"
#include "slam/frontend/rtabmap/visual_vocabulary.hpp"
#include "slam/optimize/pose_graph_optimizer.hpp"

namespace wifislam::slam::frontend::rtabmap {

/// What happened to one node (a row of rtabmap_memory.csv).
struct RtabmapNodeRecord {
  graph::KeyframeId node = -1;
  std::size_t stm = 0, wm = 0, ltm = 0;  // after the node's memory management
  int entered_wm = 0;                    // from STM or retrieved this step
  int retrieved = 0;                     // around the last best hypothesis
  int wifi_retrieved = 0;                // of similar Wi-Fi clusters
  int transferred = 0;                   // WM -> LTM
  int immune = 0;                        // WM nodes kept by Wi-Fi immunisation this step
  bool rehearsed = false;                // merged with the previous node
  std::size_t words = 0;                 // searched dictionary size after the node
  std::int64_t word_comparisons = 0;     // descriptor-word distances of its quantisation
  std::size_t scored = 0;                // WM nodes the likelihood was computed for
  std::int64_t likelihood_terms = 0;
  std::size_t hypotheses = 0;  // of the Bayes filter's posterior (0 when nothing was scored)
  graph::KeyframeId best = -1;
  double best_probability = 0.0;
  double virtual_probability = 1.0;
  graph::KeyframeId loop_candidate = -1;  // best hypothesis at or above Rtabmap/LoopThr
  bool loop_verified = false, loop_accepted = false;
  int verifications = 0;
  int loop_verifications = 0;    // of the loop candidate (role long_term): 0 or 1
  int proximity_candidates = 0;  // RGBD/ProximityBySpace candidates verified
  /// Thread CPU time of three of RTAB-Map's timing categories (Rtabmap::process statistics):
  /// memory update (quantisation into the vocabulary, STM, rehearsal), likelihood computation
  /// (tf-idf and normalisation) and posterior computation (Bayes filter). They calibrate the
  /// cost model term by term, and the last two are half of the loop-closure time (the other half,
  /// the loop hypothesis' verification, is the pipeline's: timing.json role long_term).
  double memory_update_cpu_ms = 0.0, likelihood_cpu_ms = 0.0, posterior_cpu_ms = 0.0;
  /// The cost model's share of loop-closure detection: likelihood, posterior and the loop
  /// hypothesis' verification (what Wi-Fi bounding acts on).
  double loop_closure_cost_ms = 0.0;
  /// Cost model, wall-clock, and CPU time of this thread (what wall-clock would be on an idle
  /// core: the calibration's reference on a shared machine), from selection to memory management.
  double cost_ms = 0.0, wall_ms = 0.0, cpu_ms = 0.0;
  double over_budget_ms = 0.0;  // time (of time_source) over Rtabmap/TimeThr
};

class RtabmapFrontEnd final : public FrontEnd {
 public:
  RtabmapFrontEnd(const RtabmapOptions& options, const optimize::PoseGraphOptions& graph_options);

  /// STM and WM nodes may be compared (STM: predecessors, relocalisation); LTM nodes may not.
  bool searchable(graph::KeyframeId keyframe) const override;
  std::vector<Candidate> select(const SelectionQuery& query) override;

  const RtabmapOptions& options() const { return options_; }
  const rtabmap::NodeMemory& memory() const { return memory_; }
  const rtabmap::BayesFilter& bayes_filter() const { return filter_; }
  const rtabmap::VisualVocabulary& vocabulary() const { return vocabulary_; }
  const std::vector<RtabmapNodeRecord>& records() const { return records_; }
  /// Nodes moved to LTM by the last node's memory management.
  const std::vector<graph::KeyframeId>& last_transferred() const { return last_transferred_; }
  /// The processing time of `record` as the threshold sees it.
  double node_time_ms(const RtabmapNodeRecord& record) const;

 protected:
  void after_verification(const VerificationReport& report) override;
  void write_own_outputs(const std::filesystem::path& run_dir) const override;
  nlohmann::json own_summary() const override;

 private:
  /// What step 4 found: the normalised likelihood of each scored WM node, and the Bayes filter's
  /// best hypothesis with its posterior probability ({-1, 0}: nothing was scored).
  struct HypothesisScores {
    std::pair<graph::KeyframeId, double> best{-1, 0.0};
    std::map<rtabmap::NodeId, double> likelihood;
  };

  /// Starts node `query.keyframe`'s record and clocks, and forgets the previous step's sets.
  void start_node(const SelectionQuery& query);
  /// Thread CPU time since the previous phase of select ended (or since the node started).
  double phase_cpu_ms();
  /// Step 1: the node's words into the vocabulary, and the node into STM.
  void add_to_memory(const SelectionQuery& query);
  /// Step 2: merge with the previous node when it is in STM and similar enough.
  void rehearse(graph::KeyframeId t);
  /// Step 3: retrieval around the last node's best hypothesis, nearest first, newest first within
  /// a margin (Rtabmap::process sorts each margin's ids in reverse).
  void retrieve_around_last_best();
  /// Step 3, Wi-Fi: the nodes of similar clusters (up to wifi_max_immune) are immune this step;
  /// those in LTM come back (up to wifi_max_retrieved).
  void retrieve_similar_wifi_clusters();
  /// Step 4: likelihood of node `t` over WM (bounded by Wi-Fi), then the Bayes filter.
  HypothesisScores update_hypotheses(graph::KeyframeId t);
  /// Steps 5 and 6: the predecessor, the loop hypothesis and proximity candidates, leaving out
  /// the keyframes already compared.
  std::vector<Candidate> candidates_of(const SelectionQuery& query, const HypothesisScores& scores);
  void retrieve(graph::KeyframeId node, RtabmapNodeRecord& record);
  /// Graph neighbours of `node` within `max_margin` links over nodes in memory, with margins.
  std::map<rtabmap::NodeId, int> neighbours_in_memory(graph::KeyframeId node, int max_margin,
                                                      bool include_ltm) const;
  bool linked_to_stm(graph::KeyframeId node) const;
  /// Wi-Fi immunisation: the WM and LTM nodes of the current node's similar clusters, at most
  /// wifi_max_immune of them (0: all), from the most similar cluster down, newest first within
  /// a cluster. The LTM ones are what cluster retrieval brings back.
  std::vector<graph::KeyframeId> wifi_immune_nodes() const;
  /// Step 6: proximity candidates of node `t` given the likelihood of the WM nodes scored.
  std::vector<graph::KeyframeId> proximity_candidates(
      graph::KeyframeId t, const std::map<rtabmap::NodeId, double>& likelihood);

  RtabmapOptions options_;
  rtabmap::VisualVocabulary vocabulary_;
  rtabmap::NodeMemory memory_;
  rtabmap::BayesFilter filter_;
  std::map<rtabmap::NodeId, rtabmap::NodeWords> words_of_;
  const graph::PoseGraph* graph_ = nullptr;  // the pipeline's, seen through the selection query
  graph::KeyframeId last_best_ = -1;         // best hypothesis of the previous node (retrieval)
  std::set<graph::KeyframeId> immune_now_;   // retrieval neighbourhood of this step
  std::vector<graph::KeyframeId>
      wifi_immune_;  // Wi-Fi immunisation of this step (wifi_immune_nodes)
  RtabmapNodeRecord pending_;
  std::chrono::steady_clock::time_point started_;
  double started_cpu_ms_ = 0.0;
  double phase_started_cpu_ms_ = 0.0;  // start of select's current timing phase (phase_cpu_ms)
  std::vector<RtabmapNodeRecord> records_;
  std::vector<graph::KeyframeId> last_transferred_;
};

}  // namespace wifislam::slam::frontend::rtabmap
