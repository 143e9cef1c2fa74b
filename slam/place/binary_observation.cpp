#include "slam/place/binary_observation.hpp"

#include <algorithm>
#include <cstring>

namespace wifislam::slam::place {

bool BinaryObservation::has(int word) const {
  return std::binary_search(present.begin(), present.end(), word);
}

BinaryObservation visual_words(const bow::VocabularyTree& vocabulary, const cv::Mat& descriptors) {
  BinaryObservation out;
  for (int r = 0; r < descriptors.rows; ++r) {
    match::PackedDescriptor d{};
    std::memcpy(d.data(), descriptors.ptr(r), sizeof(d));  // 32-byte ORB rows, as the tree reads
    out.present.push_back(static_cast<int>(vocabulary.word_of(d)));
  }
  std::sort(out.present.begin(), out.present.end());
  out.present.erase(std::unique(out.present.begin(), out.present.end()), out.present.end());
  return out;
}

BinaryObservation concatenate(const BinaryObservation& observation, const BinaryObservation& extra,
                              int offset) {
  BinaryObservation out = observation;
  for (int word : extra.present) out.present.push_back(offset + word);
  std::sort(out.present.begin(), out.present.end());
  out.present.erase(std::unique(out.present.begin(), out.present.end()), out.present.end());
  return out;
}

}  // namespace wifislam::slam::place
