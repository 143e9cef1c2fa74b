#pragma once
// ORB-SLAM2's keyframe database (Mur-Artal & Tardós 2017; KeyFrameDatabase.cc) over our BoW
// vectors: an inverted index word -> keyframes holding it, and DetectLoopCandidates, the first
// stage of loop detection. The ORB-SLAM-style front end keeps one database for all keyframes
// (vanilla) or one per Wi-Fi cluster (the paper's per-cluster dictionaries), which is why the
// database is a plain object with no knowledge of clusters.
//
// loop_candidates(query), as DetectLoopCandidates does it:
//  1. keyframes sharing a word with the query, except those `connected` to it (its covisible
//     keyframes), with the number of words they share;
//  2. of those sharing more than 0.8 x the most shared words, the ones whose L1 score with the
//     query is at least `min_score` (ORB-SLAM2: the lowest score between the query and its
//     covisible keyframes);
//  3. each scored keyframe with its best covisible neighbours (`neighbours`, ORB-SLAM2: the 10 best
//     by covisibility weight) forms a group; the group's score accumulates the scores of those
//     neighbours that were scored in step 2, and the group is represented by its best-scoring
//     keyframe;
//  4. groups whose accumulated score exceeds 0.75 x the best accumulated score give their
//     representative (each keyframe once), in decreasing accumulated score (ties: lower id).

#include <functional>
#include <map>
#include <vector>

#include "slam/bow/bow_vector.hpp"
#include "slam/graph/pose_graph.hpp"

namespace wifislam::slam::bow {

struct LoopCandidate {
  graph::KeyframeId keyframe = -1;
  double score = 0.0;              // its own L1 score with the query
  double accumulated_score = 0.0;  // its group's
};

/// The covisible neighbours of a keyframe to group with it (best first).
using NeighbourFunction = std::function<std::vector<graph::KeyframeId>(graph::KeyframeId)>;

class KeyframeDatabase {
 public:
  /// Adds a keyframe's BoW vector to the inverted index. A keyframe is added once.
  void add(graph::KeyframeId keyframe, const BowVector& vector);
  void erase(graph::KeyframeId keyframe);

  bool contains(graph::KeyframeId keyframe) const { return vectors_.count(keyframe) > 0; }
  std::size_t size() const { return vectors_.size(); }
  const BowVector& vector_of(graph::KeyframeId keyframe) const { return vectors_.at(keyframe); }
  /// Keyframes holding `word`, ascending.
  std::vector<graph::KeyframeId> keyframes_with(WordId word) const;

  std::vector<LoopCandidate> loop_candidates(const BowVector& query,
                                             const std::vector<graph::KeyframeId>& connected,
                                             double min_score,
                                             const NeighbourFunction& neighbours) const;

  /// Posting-list entries read by the last loop_candidates call (the work the Wi-Fi variant's
  /// per-cluster databases save).
  std::size_t last_postings_read() const { return last_postings_read_; }

 private:
  friend std::vector<LoopCandidate> loop_candidates(const std::vector<const KeyframeDatabase*>&,
                                                    const BowVector&,
                                                    const std::vector<graph::KeyframeId>&, double,
                                                    const NeighbourFunction&, std::size_t*);
  std::map<WordId, std::vector<graph::KeyframeId>> inverted_;  // each list ascending
  std::map<graph::KeyframeId, BowVector> vectors_;
  mutable std::size_t last_postings_read_ = 0;
};

/// DetectLoopCandidates over the union of several databases (which hold disjoint keyframes): the
/// Wi-Fi variant looks up the indexes of the current keyframe's similar clusters only. The same
/// result as one database holding all their keyframes. `postings_read` (optional) gets the
/// posting-list entries read.
std::vector<LoopCandidate> loop_candidates(const std::vector<const KeyframeDatabase*>& databases,
                                           const BowVector& query,
                                           const std::vector<graph::KeyframeId>& connected,
                                           double min_score, const NeighbourFunction& neighbours,
                                           std::size_t* postings_read = nullptr);

}  // namespace wifislam::slam::bow
