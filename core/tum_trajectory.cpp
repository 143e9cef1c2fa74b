#include "core/tum_trajectory.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam {

StampedPose StampedPose::from_pose(Timestamp time, const Pose& pose) {
  StampedPose s;
  s.time = time;
  s.translation_m = pose.translation();
  s.rotation = Eigen::Quaterniond(pose.linear()).normalized();
  if (s.rotation.w() < 0) s.rotation.coeffs() *= -1.0;  // one canonical sign
  return s;
}

std::string format_tum_line(const StampedPose& p) {
  std::string line = p.time.to_tum_string();
  for (double v : {p.translation_m.x(), p.translation_m.y(), p.translation_m.z(), p.rotation.x(),
                   p.rotation.y(), p.rotation.z(), p.rotation.w()}) {
    line += ' ';
    line += format_double_exact(v);
  }
  return line;
}

StampedPose parse_tum_pose_fields(const std::vector<std::string_view>& fields,
                                  const std::string& where) {
  if (fields.size() != 8) {
    throw ParseError(
        where, "",
        fmt::format("expected 8 fields 'timestamp tx ty tz qx qy qz qw', got {}", fields.size()));
  }
  // As the TUM tools read a stamp (float()): numpy.savetxt writes "1.7e+09" by default.
  const auto time = Timestamp::parse_rounded(fields[0]);
  if (!time) throw ParseError(where, "", fmt::format("bad timestamp '{}'", fields[0]));
  double v[7];
  for (int i = 0; i < 7; ++i) {
    if (!parse_double(fields[i + 1], v[i])) {
      throw ParseError(where, "",
                       fmt::format("field {} is not a finite number: '{}'", i + 2, fields[i + 1]));
    }
    if (i < 3 && std::abs(v[i]) > kMaxTrajectoryCoordinateM) {
      throw ParseError(where, "",
                       fmt::format("field {} ({} m) is beyond {:g} m from the origin: not a "
                                   "physical position",
                                   i + 2, fields[i + 1], kMaxTrajectoryCoordinateM));
    }
  }
  StampedPose p;
  p.time = *time;
  p.translation_m = Eigen::Vector3d(v[0], v[1], v[2]);
  p.rotation = Eigen::Quaterniond(v[6], v[3], v[4], v[5]);
  if (p.rotation.norm() < 1e-6) throw ParseError(where, "", "quaternion has zero length");
  return p;
}

void require_later_stamp(std::optional<Timestamp>& last, Timestamp time, std::string_view field,
                         const std::string& where) {
  if (last && !(*last < time)) {
    throw ParseError(where, "",
                     fmt::format("timestamp {} is not later than the previous line's ({}); "
                                 "stamps must increase from line to line",
                                 field, last->to_tum_string()));
  }
  last = time;
}

Trajectory read_tum_trajectory(const std::string& path) {
  Trajectory out;
  std::optional<Timestamp> last;
  // Streamed: a bad line stops the reading there, and blank lines cost nothing.
  for_each_text_line(path, [&](const TextLine& line) {
    const auto fields = split_fields(line.text);
    if (fields.empty() || fields[0].front() == '#') return;
    const std::string where = path + ":" + std::to_string(line.number);
    StampedPose p = parse_tum_pose_fields(fields, where);
    require_later_stamp(last, p.time, fields[0], where);
    out.push_back(p);
  });
  return out;
}

void write_tum_trajectory(const std::string& path, const Trajectory& trajectory,
                          const std::vector<std::string>& header) {
  std::string text;
  for (const auto& h : header) text += "# " + h + "\n";
  for (const auto& p : trajectory) {
    if (!p.translation_m.allFinite() || !p.rotation.coeffs().allFinite()) {
      throw InvalidInputError(path +
                              ": refusing to write a non-finite pose at t=" + p.time.to_string());
    }
    text += format_tum_line(p);
    text += '\n';
  }
  write_file_atomic(path, text);
}

}  // namespace wifislam
