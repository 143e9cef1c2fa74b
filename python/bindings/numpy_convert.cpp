#include "python/bindings/numpy_convert.hpp"

#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

#include <fmt/core.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "sim/scene/scene_schema.hpp"

namespace wifislam::python {

namespace py = pybind11;

py::array_t<std::uint8_t> rgb_array(const cv::Mat& bgr) {
  py::array_t<std::uint8_t> out({bgr.rows, bgr.cols, 3});
  cv::Mat rgb(bgr.rows, bgr.cols, CV_8UC3, out.mutable_data());
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return out;
}

namespace {
/// Refuses an image with no pixels or bigger than a scene's camera can be (no dataset holds
/// one, and past 2**31 rows OpenCV's int sizes overflow).
void check_image_shape(py::ssize_t rows, py::ssize_t cols, const std::string& what) {
  if (rows == 0 || cols == 0)
    throw InvalidInputError(what + ": the image is empty (0 rows or columns)");
  const double most = sim::scene::schema::kImageSidePx.hi;
  if (static_cast<double>(rows) > most || static_cast<double>(cols) > most) {
    throw InvalidInputError(
        fmt::format("{}: the image is {} x {}; at most {} x {} (the largest "
                    "camera a scene can have)",
                    what, cols, rows, most, most));
  }
}
}  // namespace

cv::Mat bgr_mat(const py::array& rgb, const std::string& what) {
  const auto image = py::array_t<std::uint8_t, py::array::c_style>::ensure(rgb);
  if (!image || rgb.dtype().kind() != 'u' || rgb.itemsize() != 1 || image.ndim() != 3 ||
      image.shape(2) != 3) {
    throw InvalidInputError(what + ": expected an H x W x 3 uint8 RGB array");
  }
  check_image_shape(image.shape(0), image.shape(1), what);
  const cv::Mat view(static_cast<int>(image.shape(0)), static_cast<int>(image.shape(1)), CV_8UC3,
                     const_cast<std::uint8_t*>(image.data()));
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

py::array_t<float> depth_array(const cv::Mat& depth_m) {
  py::array_t<float> out({depth_m.rows, depth_m.cols});
  float* dst = out.mutable_data();
  for (int r = 0; r < depth_m.rows; ++r) {
    const float* src = depth_m.ptr<float>(r);
    for (int c = 0; c < depth_m.cols; ++c) {
      *dst++ = src[c] > 0.0f ? src[c] : std::numeric_limits<float>::quiet_NaN();
    }
  }
  return out;
}

cv::Mat depth_mat(const py::array& depth_m, const std::string& what) {
  if (depth_m.dtype().kind() != 'f' || depth_m.ndim() != 2) {
    throw InvalidInputError(what + ": expected an H x W float array of metres");
  }
  check_image_shape(depth_m.shape(0), depth_m.shape(1), what);
  const auto metres =
      py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(depth_m);
  cv::Mat out(static_cast<int>(metres.shape(0)), static_cast<int>(metres.shape(1)), CV_32FC1);
  const float* src = metres.data();
  for (int r = 0; r < out.rows; ++r) {
    float* row = out.ptr<float>(r);
    for (int c = 0; c < out.cols; ++c, ++src) row[c] = std::isfinite(*src) && *src > 0 ? *src : 0;
  }
  return out;
}

py::array_t<double> pose_array(const Pose& pose) {
  py::array_t<double> out({4, 4});
  auto m = out.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = pose.matrix()(r, c);
  return out;
}

Pose pose_from_array(const py::array& pose, const std::string& what) {
  const auto m = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(pose);
  if (!m || m.ndim() != 2 || m.shape(0) != 4 || m.shape(1) != 4) {
    throw InvalidInputError(what + ": expected a 4 x 4 camera-to-world pose");
  }
  Eigen::Matrix4d matrix;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix(r, c) = m.at(r, c);
  if (!matrix.allFinite()) throw InvalidInputError(what + ": the pose has a NaN or infinity");
  const Eigen::Matrix3d rotation = matrix.topLeftCorner<3, 3>();
  const double orthogonality =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm();
  if (orthogonality > 1e-6 || rotation.determinant() < 0 ||
      (matrix.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 0) {
    throw InvalidInputError(
        fmt::format("{}: not a rigid transform (rotation off by {:.2g}, or last row not 0 0 0 1)",
                    what, orthogonality));
  }
  Pose out = Pose::Identity();
  out.matrix() = matrix;
  return out;
}

py::array_t<double> trajectory_array(const Trajectory& trajectory) {
  py::array_t<double> out({static_cast<py::ssize_t>(trajectory.size()), py::ssize_t{8}});
  auto m = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const StampedPose& p = trajectory[i];
    const double row[8] = {p.time.seconds(),    p.translation_m.x(), p.translation_m.y(),
                           p.translation_m.z(), p.rotation.x(),      p.rotation.y(),
                           p.rotation.z(),      p.rotation.w()};
    for (int c = 0; c < 8; ++c) m(static_cast<py::ssize_t>(i), c) = row[c];
  }
  return out;
}

py::array_t<double> imu_array(const std::vector<ImuReading>& readings) {
  py::array_t<double> out({static_cast<py::ssize_t>(readings.size()), py::ssize_t{7}});
  auto m = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const ImuReading& r = readings[i];
    const double row[7] = {r.time.seconds(),
                           r.angular_velocity_radps.x(),
                           r.angular_velocity_radps.y(),
                           r.angular_velocity_radps.z(),
                           r.specific_force_mps2.x(),
                           r.specific_force_mps2.y(),
                           r.specific_force_mps2.z()};
    for (int c = 0; c < 7; ++c) m(static_cast<py::ssize_t>(i), c) = row[c];
  }
  return out;
}

Trajectory trajectory_from_array(const py::array& rows, const std::string& what) {
  const auto m = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(rows);
  if (!m || m.ndim() != 2 || m.shape(1) != 8) {
    throw InvalidInputError(
        what + ": expected an N x 8 array of TUM rows (t, tx, ty, tz, qx, qy, qz, qw)");
  }
  // Each row goes through the trajectory file's own line check, as its text.
  Trajectory trajectory;
  std::optional<Timestamp> last;
  for (py::ssize_t i = 0; i < m.shape(0); ++i) {
    std::vector<std::string> text;
    const double t_s = m.at(i, 0);
    // Nanoseconds in 64 bits reach 9.2e9 s (the year 2262): a stamp beyond has no Timestamp, and
    // the usual cause is milliseconds (or microseconds) given as seconds.
    if (!std::isfinite(t_s) || std::abs(t_s) >= 9.2e9) {
      throw ParseError(fmt::format("{} row {}", what, i), "",
                       std::isfinite(t_s)
                           ? fmt::format("t = {} s is out of range (at most 9.2e9 s; stamps are "
                                         "seconds, not milliseconds)",
                                         t_s)
                           : fmt::format("t is not a finite number ({})", t_s));
    }
    // The stamp as the decimal the float was written as (nanoseconds at most), exactly; the rest
    // fixed point, as the pose reader checks them.
    text.push_back(Timestamp::from_seconds_exact(t_s).to_string(9));
    for (int c = 1; c < 8; ++c) text.push_back(fmt::format("{:.17f}", m.at(i, c)));
    const std::vector<std::string_view> fields(text.begin(), text.end());
    const std::string where = fmt::format("{} row {}", what, i);
    StampedPose pose = parse_tum_pose_fields(fields, where);
    require_later_stamp(last, pose.time, "t", where);
    trajectory.push_back(pose);
  }
  return trajectory;
}

}  // namespace wifislam::python
