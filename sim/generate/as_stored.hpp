#pragma once
// What a dataset keeps of an event, for the consumers that take events in memory instead of
// reading the dataset back (the in-memory stream, runs fed while their dataset is written): they
// must see exactly what a reader of the dataset sees, or a run on the scene and a run on its
// dataset part in their last bits and, through a different keyframe, in everything after.
//
//   depth:    16-bit PNG units (1/5000 m), decoded to metres as the reader does;
//   odometry: odometry.txt keeps the translation and the quaternion to the last bit (exact
//             decimals), and the reader rebuilds the rotation from the quaternion, which is not
//             the matrix it came from in its last bits;
//   colour (lossless PNG), stamps (exact decimals) and Wi-Fi scans (integers) come back as they
//   went in.

#include <opencv2/core/mat.hpp>

#include "core/sensor_stream.hpp"

namespace wifislam::sim::generate {

/// The metres a reader decodes from depth's PNG units (CV_16UC1, sim/render/depth_png.hpp).
cv::Mat depth_as_stored(const cv::Mat& depth_units);

/// The reading as the dataset reader returns it from odometry.txt.
OdometryReading odometry_as_stored(const OdometryReading& reading);

}  // namespace wifislam::sim::generate
