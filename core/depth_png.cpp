#include "core/depth_png.hpp"

#include <cmath>
#include <cstdint>

namespace wifislam {

cv::Mat depth_to_png_units(const cv::Mat& depth_m, double units_per_metre) {
  CV_Assert(depth_m.type() == CV_32FC1);
  cv::Mat units(depth_m.size(), CV_16UC1);
  for (int y = 0; y < depth_m.rows; ++y) {
    const float* in = depth_m.ptr<float>(y);
    auto* out = units.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      const double value = std::nearbyint(static_cast<double>(in[x]) * units_per_metre);
      out[x] = (value > 0.0 && value <= 65535.0) ? static_cast<std::uint16_t>(value) : 0;
    }
  }
  return units;
}

cv::Mat depth_from_png_units(const cv::Mat& depth_units, double units_per_metre) {
  CV_Assert(depth_units.type() == CV_16UC1);
  cv::Mat depth_m;
  depth_units.convertTo(depth_m, CV_32FC1, 1.0 / units_per_metre);
  return depth_m;
}

}  // namespace wifislam
