#include "core/imu_csv.hpp"

#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam {

namespace {

/// A value no IMU reads: a corrupt row (1e30), refused where it is rather than handed to another
/// program by `export`. Far above any real unit's range (MEMS parts stop near 16 g and 35 rad/s),
/// because simulated ones go beyond it legitimately: the motion profile changes speed in one
/// step at a pause, a spike of speed x rate (5 m/s at 2000 Hz: 1e4 m/s^2), and the schema allows
/// noise densities whose white noise alone reaches hundreds of m/s^2.
constexpr double kMaxSpecificForceMps2 = 1e6;
constexpr double kMaxAngularVelocityRadps = 1e6;

constexpr std::array<const char*, 7> kColumns = {"timestamp", "w_x_radps", "w_y_radps", "w_z_radps",
                                                 "a_x_mps2",  "a_y_mps2",  "a_z_mps2"};

}  // namespace

std::string imu_csv_header() {
  std::string h;
  for (const char* c : kColumns) h += (h.empty() ? "" : ",") + std::string(c);
  return h;
}

std::string format_imu_csv_row(const ImuReading& r) {
  const Eigen::Vector3d& w = r.angular_velocity_radps;
  const Eigen::Vector3d& a = r.specific_force_mps2;
  return fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", r.time.to_tum_string(),
                     w.x(), w.y(), w.z(), a.x(), a.y(), a.z());
}

std::vector<ImuReading> read_imu_csv(const std::string& path) {
  std::vector<ImuReading> readings;
  std::optional<Timestamp> last;
  for_each_csv_row(path, kColumns, [&](const CsvRow& row) {
    ImuReading r;
    const auto time = Timestamp::parse(row.fields[0]);
    if (!time) {
      throw ParseError(row.where, kColumns[0],
                       fmt::format("'{}' is not a time in seconds", row.fields[0]));
    }
    r.time = *time;
    if (last && !(r.time > *last)) {
      throw ParseError(row.where, kColumns[0],
                       fmt::format("{} does not come after the row before ({})",
                                   r.time.to_tum_string(), last->to_tum_string()));
    }
    last = r.time;
    for (std::size_t i = 1; i < kColumns.size(); ++i) {
      double v = 0.0;
      if (!parse_double(row.fields[i], v) || !std::isfinite(v)) {
        throw ParseError(row.where, kColumns[i],
                         fmt::format("'{}' is not a finite number", row.fields[i]));
      }
      const double most = i <= 3 ? kMaxAngularVelocityRadps : kMaxSpecificForceMps2;
      if (std::abs(v) > most) {
        throw ParseError(row.where, kColumns[i],
                         fmt::format("{} is beyond what any IMU reads (at most {:g} {})",
                                     row.fields[i], most, i <= 3 ? "rad/s" : "m/s^2"));
      }
      (i <= 3 ? r.angular_velocity_radps : r.specific_force_mps2)[(i - 1) % 3] = v;
    }
    readings.push_back(r);
  });
  return readings;
}

}  // namespace wifislam
