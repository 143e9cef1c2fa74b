#pragma once
// A 32-byte ORB descriptor, one row of a CV_8U descriptor matrix, as the four 64-bit words that
// every exhaustive Hamming search here works on (hamming_distances.hpp).

#include <cstring>

#include <opencv2/core/mat.hpp>

#include "slam/match/hamming_distances.hpp"

namespace wifislam::slam::match {

/// Whether `descriptors` holds 32-byte ORB descriptors: CV_8U, 32 columns.
inline bool are_orb_descriptors(const cv::Mat& descriptors) {
  return descriptors.type() == CV_8U &&
         descriptors.cols == static_cast<int>(sizeof(PackedDescriptor));
}

/// Row `row` of a matrix for which are_orb_descriptors holds, copied (rows need not be aligned).
inline PackedDescriptor packed_descriptor(const cv::Mat& descriptors, int row) {
  PackedDescriptor out;
  std::memcpy(out.data(), descriptors.ptr(row), sizeof(out));
  return out;
}

}  // namespace wifislam::slam::match
