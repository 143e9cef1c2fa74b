#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace wifislam::slam::rtabmap {

VisualVocabulary::VisualVocabulary(double nndr_ratio) : nndr_ratio_(nndr_ratio) {}

NodeWords VisualVocabulary::add_node(NodeId node, const cv::Mat& descriptors) {
  NodeWords out;
  if (descriptors.empty()) return out;
  if (descriptors.type() != CV_8U) {
    throw std::invalid_argument("VisualVocabulary: descriptors must be CV_8U (ORB)");
  }
  // Distances to the words that existed before this node, in one batch.
  const int existing = descriptors_.rows;
  cv::Mat distances;
  if (existing > 0) {
    cv::batchDistance(descriptors, descriptors_, distances, CV_32S, cv::noArray(),
                      cv::NORM_HAMMING);
    distance_computations_ += static_cast<std::int64_t>(descriptors.rows) * existing;
  }
  for (int i = 0; i < descriptors.rows; ++i) {
    int best = std::numeric_limits<int>::max(), second = std::numeric_limits<int>::max();
    WordId best_word = -1;
    const auto consider = [&](int d, WordId w) {
      if (d < best) {
        second = best;
        best = d;
        best_word = w;
      } else if (d < second) {
        second = d;
      }
    };
    for (int w = 0; w < existing; ++w) consider(distances.at<int>(i, w), w);
    // Words founded earlier in this node.
    for (int w = existing; w < descriptors_.rows; ++w) {
      consider(
          static_cast<int>(cv::norm(descriptors.row(i), descriptors_.row(w), cv::NORM_HAMMING)), w);
      ++distance_computations_;
    }
    const bool matched = descriptors_.rows >= 2 &&
                         static_cast<double>(best) <= nndr_ratio_ * static_cast<double>(second);
    WordId word = best_word;
    if (!matched) {
      word = descriptors_.rows;
      descriptors_.push_back(descriptors.row(i));
      references_.emplace_back();
    }
    ++out.counts[word];
    ++out.total;
  }
  enable_references(node, out);
  return out;
}

void VisualVocabulary::disable_references(NodeId node, const NodeWords& words) {
  for (const auto& [word, count] : words.counts) {
    references_.at(static_cast<std::size_t>(word)).erase(node);
  }
}

void VisualVocabulary::enable_references(NodeId node, const NodeWords& words) {
  for (const auto& [word, count] : words.counts) {
    references_.at(static_cast<std::size_t>(word))[node] = count;
  }
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
