#include "eval/alignment.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/error.hpp"

namespace wifislam::eval {

const char* to_string(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::kNone:
      return "none";
    case AlignmentMode::kSe3:
      return "se3";
    case AlignmentMode::kSim3:
      return "sim3";
  }
  return "se3";
}

std::optional<AlignmentMode> parse_alignment_mode(std::string_view text) {
  for (AlignmentMode m : {AlignmentMode::kNone, AlignmentMode::kSe3, AlignmentMode::kSim3}) {
    if (text == to_string(m)) return m;
  }
  return std::nullopt;
}

Pose Alignment::apply(const Pose& pose) const {
  Pose out = Pose::Identity();
  out.linear() = rotation * pose.linear();
  out.translation() = apply(Eigen::Vector3d(pose.translation()));
  return out;
}

Alignment align_points(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                       bool with_scale) {
  if (source.cols() != target.cols()) {
    throw InvalidInputError("alignment: point counts differ");
  }
  if (source.cols() < 3) {
    throw InvalidInputError("alignment: needs at least 3 associated poses, got " +
                            std::to_string(source.cols()));
  }
  if (with_scale) {
    // Umeyama's scale divides by the source's spread: positions that all coincide (a stationary
    // estimate) have no scale to find, and gave NaN for every error.
    const Eigen::Vector3d centre = source.rowwise().mean();
    const double spread_m2 = (source.colwise() - centre).squaredNorm() / source.cols();
    if (!(spread_m2 > 1e-12)) {
      throw InvalidInputError(
          fmt::format("sim3 alignment: the {} associated estimated positions coincide (spread "
                      "{:.3g} m RMS), so they have no scale to fit; align with se3",
                      source.cols(), std::sqrt(spread_m2)));
    }
  }
  const Eigen::Matrix4d t = Eigen::umeyama(source, target, with_scale);
  Alignment a;
  const Eigen::Matrix3d sr = t.topLeftCorner<3, 3>();
  // umeyama returns [sR t; 0 1]; the columns of sR all have norm s.
  a.scale = with_scale ? sr.col(0).norm() : 1.0;
  a.rotation = sr / a.scale;
  a.translation_m = t.topRightCorner<3, 1>();
  return a;
}

}  // namespace wifislam::eval
