#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam::rtabmap {

namespace {

std::array<std::uint64_t, 4> packed(const cv::Mat& descriptors, int row) {
  std::array<std::uint64_t, 4> out{};
  std::memcpy(out.data(), descriptors.ptr(row), 32);
  return out;
}

}  // namespace

VisualVocabulary::VisualVocabulary(double nndr_ratio) : nndr_ratio_(nndr_ratio) {}

NodeWords VisualVocabulary::add_node(NodeId node, const cv::Mat& descriptors) {
  NodeWords out;
  if (descriptors.empty()) return out;
  if (descriptors.type() != CV_8U || descriptors.cols != 32) {
    throw std::invalid_argument("VisualVocabulary: descriptors must be 32-byte ORB rows (CV_8U)");
  }
  refresh_dictionary();
  std::vector<int> distances;
  for (int i = 0; i < descriptors.rows; ++i) {
    const std::array<std::uint64_t, 4> query = packed(descriptors, i);
    // Every word of the dictionary, including those this node founded a moment ago.
    distances.resize(dictionary_ids_.size());
    hamming_distances(query.data(), dictionary_words_.data(), distances.size(), distances.data());
    distance_computations_ += static_cast<std::int64_t>(distances.size());
    int best = std::numeric_limits<int>::max(), second = std::numeric_limits<int>::max();
    WordId best_word = -1;
    for (std::size_t w = 0; w < distances.size(); ++w) {
      const int d = distances[w];
      if (d < best) {
        second = best;
        best = d;
        best_word = dictionary_ids_[w];
      } else if (d < second) {
        second = d;
      }
    }
    const bool matched = distances.size() >= 2 &&
                         static_cast<double>(best) <= nndr_ratio_ * static_cast<double>(second);
    WordId word = best_word;
    if (!matched) {
      word = static_cast<WordId>(size());
      words_.insert(words_.end(), query.begin(), query.end());
      references_.emplace_back();
      dictionary_words_.insert(dictionary_words_.end(), query.begin(), query.end());
      dictionary_ids_.push_back(word);
    }
    ++out.counts[word];
    ++out.total;
  }
  enable_references(node, out);
  return out;
}

void VisualVocabulary::disable_references(NodeId node, const NodeWords& words) {
  for (const auto& [word, count] : words.counts) {
    std::map<NodeId, int>& refs = references_.at(static_cast<std::size_t>(word));
    if (refs.erase(node) > 0 && refs.empty()) dictionary_stale_ = true;
  }
}

void VisualVocabulary::enable_references(NodeId node, const NodeWords& words) {
  for (const auto& [word, count] : words.counts) {
    std::map<NodeId, int>& refs = references_.at(static_cast<std::size_t>(word));
    if (refs.empty()) dictionary_stale_ = true;
    refs[node] = count;
  }
}

void VisualVocabulary::refresh_dictionary() {
  if (!dictionary_stale_) return;
  dictionary_words_.clear();
  dictionary_ids_.clear();
  for (std::size_t w = 0; w < references_.size(); ++w) {
    if (references_[w].empty()) continue;
    dictionary_words_.insert(dictionary_words_.end(), words_.begin() + 4 * w,
                             words_.begin() + 4 * (w + 1));
    dictionary_ids_.push_back(static_cast<WordId>(w));
  }
  dictionary_stale_ = false;
}

std::size_t VisualVocabulary::dictionary_size() {
  refresh_dictionary();
  return dictionary_ids_.size();
}

cv::Mat strongest_descriptors(const std::vector<cv::KeyPoint>& keypoints,
                              const cv::Mat& descriptors, int max_features) {
  if (max_features <= 0 || descriptors.rows <= max_features) return descriptors;
  std::vector<int> order(static_cast<std::size_t>(descriptors.rows));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return keypoints[static_cast<std::size_t>(a)].response >
           keypoints[static_cast<std::size_t>(b)].response;
  });
  order.resize(static_cast<std::size_t>(max_features));
  std::sort(order.begin(), order.end());
  cv::Mat out;
  for (int row : order) out.push_back(descriptors.row(row));
  return out;
}

double node_similarity(const NodeWords& a, const NodeWords& b) {
  const int total = std::max(a.total, b.total);
  if (total <= 0) return 0.0;
  int pairs = 0;
  for (const auto& [word, count] : a.counts) {
    if (count != 1) continue;
    const auto it = b.counts.find(word);
    if (it != b.counts.end() && it->second == 1) ++pairs;
  }
  return static_cast<double>(pairs) / static_cast<double>(total);
}

}  // namespace wifislam::slam::rtabmap
