#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "slam/match/packed_descriptor.hpp"

namespace wifislam::slam::frontend::rtabmap {

VisualVocabulary::VisualVocabulary(double nndr_ratio) : nndr_ratio_(nndr_ratio) {}

NodeWords VisualVocabulary::add_node(NodeId node, const cv::Mat& descriptors) {
  NodeWords out;
  if (descriptors.empty()) return out;
  if (descriptors.type() != CV_8U || descriptors.cols != 32) {
    throw std::invalid_argument("VisualVocabulary: descriptors must be 32-byte ORB rows (CV_8U)");
  }
  refresh_dictionary();
  for (int i = 0; i < descriptors.rows; ++i) {
    const match::PackedDescriptor query = match::packed_descriptor(descriptors, i);
    // Every word of the dictionary, including those this node founded a moment ago.
    const std::uint64_t* const lanes[4] = {dictionary_lanes_[0].data(), dictionary_lanes_[1].data(),
                                           dictionary_lanes_[2].data(),
                                           dictionary_lanes_[3].data()};
    const std::size_t searched = dictionary_ids_.size();
    const match::NearestTwo nearest = match::nearest_two(query.data(), lanes, searched);
    distance_computations_ += static_cast<std::int64_t>(searched);
    const int best = nearest.best, second = nearest.second;
    const WordId best_word = searched > 0 ? dictionary_ids_[nearest.best_index] : -1;
    const bool matched =
        searched >= 2 && static_cast<double>(best) <= nndr_ratio_ * static_cast<double>(second);
    WordId word = best_word;
    if (!matched) {
      word = static_cast<WordId>(size());
      words_.insert(words_.end(), query.begin(), query.end());
      references_.emplace_back();
      for (int k = 0; k < 4; ++k) dictionary_lanes_[k].push_back(query[k]);
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
  for (auto& lane : dictionary_lanes_) lane.clear();
  dictionary_ids_.clear();
  for (std::size_t w = 0; w < references_.size(); ++w) {
    if (references_[w].empty()) continue;
    for (std::size_t k = 0; k < 4; ++k) dictionary_lanes_[k].push_back(words_[4 * w + k]);
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

}  // namespace wifislam::slam::frontend::rtabmap
