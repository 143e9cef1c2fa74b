#pragma once
// FAB-MAP's observation of an image: which words are present (a word is present when at least
// one feature falls into it; how often does not count), as the sorted list of present word ids
// out of `word_count` (openFABMAP stores the same as a 0/1 row of vocabulary size).
//
// Visual words are the leaves of our ORB vocabulary tree (slam/bow/vocabulary_tree.hpp, 10 000
// words at k 10, L 4). openFABMAP clusters SURF, which Debian's OpenCV lacks; these leaves are the
// words our ORB front end already uses, and FAB-MAP 1.0 also had a vocabulary of 10 000 words.
// Wi-Fi words (wifi_words.hpp) are appended after them.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "slam/bow/vocabulary_tree.hpp"

namespace wifislam::slam::place {

struct BinaryObservation {
  std::vector<int> present;  // ascending, unique
  bool has(int word) const;
};

/// The visual words present among an image's ORB descriptors (one row each).
BinaryObservation visual_words(const bow::VocabularyTree& vocabulary, const cv::Mat& descriptors);

/// `observation` with `extra` (ids counted from 0) appended after the first `offset` words.
BinaryObservation concatenate(const BinaryObservation& observation, const BinaryObservation& extra,
                              int offset);

}  // namespace wifislam::slam::place
