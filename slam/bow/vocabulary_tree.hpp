#pragma once
// A visual vocabulary as DBoW2 builds it (Gálvez-López & Tardós, IEEE T-RO 28(5), 2012), for the
// ORB-SLAM-style front end. No bag-of-words library is packaged for Debian, so it is written here,
// after DBoW2's TemplatedVocabulary with FORB descriptors, TF_IDF weighting and L1 scoring:
//
//  - Tree: hierarchical k-majority clustering of binary ORB descriptors, `branching` (k) children
//    per node and `depth` (L) levels. At each node the node's descriptors are clustered into k
//    groups: k-means++ seeding (a seeded stream, so training is deterministic), then assignment to
//    the nearest centre by Hamming distance (ties to the lower centre) and the bitwise majority as
//    the new centre (a bit is set when at least half the members have it, as DBoW2's
//    FORB::meanValue), until no assignment changes. A node with at most k descriptors gets one
//    child per descriptor; a child with a single descriptor, or at level L, is a leaf: a word.
//  - Weights: idf(word) = ln(N / n_word), N training images, n_word those with the word.
//  - An image's BoW vector: each descriptor descends to its nearest child at every level (ties to
//    the lower child); its word adds idf(word); the vector is L1-normalised. The direct index
//    records each descriptor under its ancestor `levels_up` levels above the leaves (ORB-SLAM uses
//    4 with its L = 6; for L <= levels_up it is level 1).
//
// File (`save`/`load`; little-endian, versioned, with a checksum so a corrupt or truncated file is
// refused, never half-read):
//   "WSLAMVOC" | u32 version (1) | u32 branching | u32 depth | u32 nodes | u32 words |
//   u32 training images | u64 training descriptors |
//   per node, parents before children: u32 parent (root: 0xffffffff) | 32-byte descriptor |
//   f64 idf (0 for inner nodes) | u32 word (0xffffffff for inner nodes) |
//   64 hex digits: SHA-256 of everything before them.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "slam/bow/bow_vector.hpp"
#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam::bow {

struct VocabularyOptions {
  int branching = 10;  // k: children per node
  int depth = 5;       // L: levels below the root
  std::uint64_t seed = 1;
  /// Assignment rounds per clustering before giving up on convergence (DBoW2 has no cap; a cap
  /// keeps training time bounded on pathological data, and is rarely reached).
  int max_iterations = 100;
};

class VocabularyTree {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  /// Trains on the descriptors of a set of images (each a CV_8U matrix of 32-byte rows; empty
  /// images are allowed). Throws std::invalid_argument for other matrix types or bad options.
  static VocabularyTree train(const std::vector<cv::Mat>& images, const VocabularyOptions& options);

  /// The image's L1-normalised tf-idf vector; with `direct_index`, its features per node
  /// `levels_up` levels above the leaves.
  BowVector transform(const cv::Mat& descriptors, FeatureVector* direct_index = nullptr,
                      int levels_up = 4) const;
  /// The word a descriptor falls into.
  WordId word_of(const match::PackedDescriptor& descriptor) const;

  int branching() const { return branching_; }
  int depth() const { return depth_; }
  std::size_t node_count() const { return nodes_.size(); }
  std::size_t word_count() const { return word_nodes_.size(); }
  double idf(WordId word) const { return nodes_[word_nodes_.at(word)].idf; }
  std::uint32_t training_images() const { return training_images_; }
  std::uint64_t training_descriptors() const { return training_descriptors_; }

  /// The file's bytes (format above).
  std::string serialise() const;
  /// Parses bytes written by serialise. InvalidInputError naming `source` and what is wrong
  /// (truncated, checksum, version, structure) otherwise.
  static VocabularyTree deserialise(std::string_view bytes, const std::string& source);
  void save(const std::filesystem::path& path) const;  // atomic
  static VocabularyTree load(const std::filesystem::path& path);

 private:
  struct Node {
    std::uint32_t parent = kNone;
    std::vector<NodeId> children;
    match::PackedDescriptor descriptor{};
    double idf = 0.0;
    WordId word = kNone;
    int level = 0;
  };
  NodeId descend(const match::PackedDescriptor& d, int stop_level, NodeId* at_level) const;

  int branching_ = 0, depth_ = 0;
  std::uint32_t training_images_ = 0;
  std::uint64_t training_descriptors_ = 0;
  std::vector<Node> nodes_;         // 0 is the root
  std::vector<NodeId> word_nodes_;  // word id -> node
};

}  // namespace wifislam::slam::bow
