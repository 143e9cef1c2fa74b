#pragma once
// Images, poses and trajectories between the library's types and numpy arrays, with the
// conventions Python users expect: colour as RGB (OpenCV keeps BGR), depth in metres with NaN
// where the sensor has no reading (the library and the PNGs use 0), poses as 4 x 4 arrays.

#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <opencv2/core/mat.hpp>

#include "core/imu_csv.hpp"
#include "core/pose.hpp"
#include "core/tum_trajectory.hpp"

namespace wifislam::python {

/// CV_8UC3 BGR -> H x W x 3 uint8 RGB (a copy).
pybind11::array_t<std::uint8_t> rgb_array(const cv::Mat& bgr);
/// H x W x 3 uint8 RGB -> CV_8UC3 BGR. Throws InvalidInputError naming `what` for another shape.
cv::Mat bgr_mat(const pybind11::array& rgb, const std::string& what);

/// CV_32FC1 metres (0 = no reading) -> H x W float32 metres, NaN = no reading.
pybind11::array_t<float> depth_array(const cv::Mat& depth_m);
/// H x W float32/float64 metres (NaN or 0 = no reading) -> CV_32FC1 with 0 = no reading.
cv::Mat depth_mat(const pybind11::array& depth_m, const std::string& what);

pybind11::array_t<double> pose_array(const Pose& pose);
/// A 4 x 4 array whose top-left 3 x 3 is a rotation. Throws InvalidInputError naming `what`.
Pose pose_from_array(const pybind11::array& pose, const std::string& what);

/// N x 8 TUM rows (t [s], tx, ty, tz, qx, qy, qz, qw), as evo and the TUM tools hold them.
pybind11::array_t<double> trajectory_array(const Trajectory& trajectory);
/// imu.csv's rows as an N x 7 array: t (s), angular velocity (rad/s) x y z, specific force
/// (m/s^2) x y z, in the IMU frame.
pybind11::array_t<double> imu_array(const std::vector<ImuReading>& readings);
/// The inverse; each row is checked as a trajectory file's line is (core/tum_trajectory.hpp), so
/// errors name `what` and the row. Stamps are rounded to whole nanoseconds.
Trajectory trajectory_from_array(const pybind11::array& rows, const std::string& what);

}  // namespace wifislam::python
