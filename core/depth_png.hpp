#pragma once
// Depth as TUM RGB-D stores it: 16-bit PNG units, dataset::kDepthUnitsPerMetre (5000) per metre,
// 0 = no reading. The one conversion each way, for the dataset writer, the dataset reader and
// whatever must see exactly what a reader sees (sim/generate/as_stored.hpp, the Python module).

#include <opencv2/core/mat.hpp>

#include "core/dataset_format.hpp"

namespace wifislam {

/// Metres (CV_32FC1, 0 = no reading) to units (CV_16UC1), rounded to the nearest unit. Depths that
/// do not fit in 16 bits (> 13.107 m at 5000 per metre) become 0 rather than a wrong reading.
cv::Mat depth_to_png_units(const cv::Mat& depth_m,
                           double units_per_metre = dataset::kDepthUnitsPerMetre);
/// Units (CV_16UC1) back to metres (CV_32FC1).
cv::Mat depth_from_png_units(const cv::Mat& depth_units,
                             double units_per_metre = dataset::kDepthUnitsPerMetre);

}  // namespace wifislam
