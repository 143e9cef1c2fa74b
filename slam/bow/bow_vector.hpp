#pragma once
// Bag-of-words vectors as DBoW2 defines them (Gálvez-López & Tardós, "Bags of Binary Words for
// Fast Place Recognition in Image Sequences", IEEE T-RO 28(5), 2012): an image's visual words
// with their tf-idf weights, L1-normalised, and the L1 score between two images,
//   s(v, w) = 1 - 1/2 | v/|v| - w/|w| |_1,
// 1 for the same words in the same proportions, 0 for no word in common.
// Also the direct index: which of an image's features fall under each node at a chosen level of
// the vocabulary tree (ORB-SLAM matches features only within a node, for speed).

#include <cstdint>
#include <map>
#include <vector>

namespace wifislam::slam::bow {

using WordId = std::uint32_t;
using NodeId = std::uint32_t;

/// Word -> weight, sorted by word (so the score is one merge).
using BowVector = std::map<WordId, double>;
/// Node at the direct index's level -> indices of the image's features under it, ascending.
using FeatureVector = std::map<NodeId, std::vector<int>>;

/// Scales `v` to unit L1 norm (unchanged when empty or all zero).
void l1_normalise(BowVector& v);

/// DBoW2's L1 score of two L1-normalised vectors, in [0, 1].
double l1_score(const BowVector& a, const BowVector& b);

}  // namespace wifislam::slam::bow
