#pragma once
// RTAB-Map's incremental visual vocabulary (VWDictionary with Kp/IncrementalDictionary true): the
// dictionary starts empty and grows as nodes arrive. Each ORB descriptor of a new node is
// quantised to its nearest word when the nearest-neighbour distance ratio test passes
// (d1 <= Kp/NndrRatio x d2, default 0.8), otherwise it founds a new word whose descriptor it is.
// Words founded earlier in the same node are searched too (RTAB-Map searches its index and, by
// brute force, the words not yet indexed).
//
// Search is brute-force Hamming over every word (slam/match/hamming_distances.hpp's nearest_two:
// eight words at a time with AVX-512 where the CPU has it, else 4 x 64-bit popcounts per word).
// RTAB-Map uses a FLANN index; at our sizes (a few hundred nodes x 500 descriptors: ~250 new
// words per node, so ~10^5 words) an exhaustive search is exact and deterministic, which an
// approximate index is not. The cost model charges every (descriptor, word) pair, whichever
// instructions compare them (calibrated at 1.87e-6 ms a pair with popcnt). Ties go to the lower
// word id.
//
// With fewer than two words the ratio test cannot be applied; the descriptor then founds a new
// word (RTAB-Map would take the single word as a match, which makes the first node's descriptors
// collapse into one word).
//
// The vocabulary also holds the inverted index of RTAB-Map's VisualWord references: for each word,
// the nodes in memory (STM and WM) that contain it and how often. A node moved to long-term memory
// gives its references up (Memory::disableWordsRef) and takes them back when retrieved. As in
// RTAB-Map (Memory::cleanUnusedWords), a word no node in memory references leaves the searched
// dictionary until a retrieved node references it again, so a new descriptor near it founds a
// new word: memory management bounds the quantisation's cost along with the likelihood's.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <opencv2/core.hpp>

namespace wifislam::slam::frontend::rtabmap {

using WordId = int;
using NodeId = int;

/// The words of one node: word id -> how many of the node's descriptors it holds.
struct NodeWords {
  std::map<WordId, int> counts;
  int total = 0;  // descriptors quantised (RTAB-Map's ni)
};

class VisualVocabulary {
 public:
  /// `nndr_ratio`: Kp/NndrRatio.
  explicit VisualVocabulary(double nndr_ratio);

  /// Quantises `descriptors` (CV_8U, 32 bytes per row) for `node`, founding words as needed, and
  /// references them from `node`. Returns the node's words. Work: one Hamming distance per
  /// (descriptor, word) pair (counted in distance_computations()).
  NodeWords add_node(NodeId node, const cv::Mat& descriptors);

  /// The node leaves memory (LTM) or comes back: its references are dropped or restored.
  void disable_references(NodeId node, const NodeWords& words);
  void enable_references(NodeId node, const NodeWords& words);

  /// Words ever founded (ids are 0..size()-1).
  std::size_t size() const { return words_.size() / 4; }
  /// Words in the searched dictionary: those referenced by a node in memory, plus any founded
  /// since the last add_node (RTAB-Map's dictionary size).
  std::size_t dictionary_size();
  /// Nodes in memory referencing `word`, with their counts.
  const std::map<NodeId, int>& references(WordId word) const {
    return references_.at(static_cast<std::size_t>(word));
  }
  std::int64_t distance_computations() const { return distance_computations_; }

 private:
  double nndr_ratio_;
  std::vector<std::uint64_t> words_;  // 4 per word (its founding descriptor), id = index
  std::vector<std::map<NodeId, int>> references_;
  std::int64_t distance_computations_ = 0;
  /// The searched dictionary, in word-id order (ties go to the lower id): packed descriptors and
  /// ids, rebuilt when a word left or rejoined it.
  void refresh_dictionary();
  std::array<std::vector<std::uint64_t>, 4> dictionary_lanes_;  // lane k: word k of each
  std::vector<WordId> dictionary_ids_;
  bool dictionary_stale_ = false;
};

/// The strongest `max_features` keypoints' descriptor rows (Kp/MaxFeatures), by response, ties by
/// index; in index order. All rows when there are no more than `max_features`.
cv::Mat strongest_descriptors(const std::vector<cv::KeyPoint>& keypoints,
                              const cv::Mat& descriptors, int max_features);

/// RTAB-Map's Signature::compareTo: words that appear exactly once in both nodes, over the larger
/// node's word count (rehearsal similarity, in [0, 1]).
double node_similarity(const NodeWords& a, const NodeWords& b);

}  // namespace wifislam::slam::frontend::rtabmap
