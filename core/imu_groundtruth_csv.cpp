#include "core/imu_groundtruth_csv.hpp"

#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam {

namespace {

constexpr std::array<const char*, 17> kImuTruthColumns = {
    "timestamp",  "p_x_m",      "p_y_m",     "p_z_m",     "q_w",      "q_x",
    "q_y",        "q_z",        "v_x_mps",   "v_y_mps",   "v_z_mps",  "bw_x_radps",
    "bw_y_radps", "bw_z_radps", "ba_x_mps2", "ba_y_mps2", "ba_z_mps2"};

}  // namespace

std::string imu_groundtruth_csv_header() {
  std::string h;
  for (const char* c : kImuTruthColumns) h += (h.empty() ? "" : ",") + std::string(c);
  return h;
}

std::string format_imu_groundtruth_csv_row(const ImuGroundTruth& s) {
  const Eigen::Vector3d& p = s.imu_to_world.translation();
  const Eigen::Quaterniond q(s.imu_to_world.linear());
  const auto x = format_double_exact;
  return fmt::format(
      "{},{},{},{},{},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
      s.time.to_tum_string(), x(p.x()), x(p.y()), x(p.z()), x(q.w()), x(q.x()), x(q.y()), x(q.z()),
      s.velocity_mps.x(), s.velocity_mps.y(), s.velocity_mps.z(), s.gyro_bias_radps.x(),
      s.gyro_bias_radps.y(), s.gyro_bias_radps.z(), s.accel_bias_mps2.x(), s.accel_bias_mps2.y(),
      s.accel_bias_mps2.z());
}

std::vector<ImuGroundTruth> read_imu_groundtruth_csv(const std::string& path) {
  std::vector<ImuGroundTruth> states;
  std::optional<Timestamp> last;
  for_each_csv_row(path, kImuTruthColumns, [&](const CsvRow& row) {
    ImuGroundTruth s;
    const auto time = Timestamp::parse(row.fields[0]);
    if (!time) {
      throw ParseError(row.where, kImuTruthColumns[0],
                       fmt::format("'{}' is not a time in seconds", row.fields[0]));
    }
    if (last && !(*time > *last)) {
      throw ParseError(row.where, kImuTruthColumns[0],
                       fmt::format("{} does not come after the row before ({})",
                                   time->to_tum_string(), last->to_tum_string()));
    }
    s.time = *time;
    last = s.time;
    double v[17] = {};
    for (std::size_t i = 1; i < kImuTruthColumns.size(); ++i) {
      if (!parse_double(row.fields[i], v[i]) || !std::isfinite(v[i])) {
        throw ParseError(row.where, kImuTruthColumns[i],
                         fmt::format("'{}' is not a finite number", row.fields[i]));
      }
    }
    const Eigen::Quaterniond q(v[4], v[5], v[6], v[7]);
    if (!(q.norm() > 1e-6)) throw ParseError(row.where, "q_w", "the quaternion has zero length");
    s.imu_to_world = pose_from_translation_quaternion({v[1], v[2], v[3]}, q);
    s.velocity_mps = {v[8], v[9], v[10]};
    s.gyro_bias_radps = {v[11], v[12], v[13]};
    s.accel_bias_mps2 = {v[14], v[15], v[16]};
    states.push_back(s);
  });
  return states;
}

}  // namespace wifislam
