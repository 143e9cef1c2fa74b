#include "core/imu_csv.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "tests/core/test_folder.hpp"

namespace wifislam {
namespace {

ImuReading imu_reading(std::int64_t us, double a_z_mps2, double w_x_radps) {
  ImuReading r;
  r.time = Timestamp::from_ns(us * 1000);
  r.specific_force_mps2 = Eigen::Vector3d(0.1, -0.2, a_z_mps2);
  r.angular_velocity_radps = Eigen::Vector3d(w_x_radps, 0.0, 0.5);
  return r;
}

std::string imu_text(const std::vector<ImuReading>& readings) {
  std::string text = imu_csv_header() + "\n";
  for (const ImuReading& r : readings) text += format_imu_csv_row(r);
  return text;
}

TEST(ImuCsv, ReadingsUpToWhatAnImuReadsReadBack) {
  const auto dir = test::fresh_folder("imu_bounds");
  test::write_text(dir / "imu.csv",
                   imu_text({imu_reading(0, 9.81, 0.0), imu_reading(5000, -1e6, 1e6)}));
  const std::vector<ImuReading> read = read_imu_csv((dir / "imu.csv").string());
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[1].specific_force_mps2.z(), -1e6);
  EXPECT_EQ(read[1].angular_velocity_radps.x(), 1e6);
}

TEST(ImuCsv, AReadingBeyondWhatAnImuReadsIsRefusedAtItsRowAndColumn) {
  const auto dir = test::fresh_folder("imu_beyond");
  const std::string file = (dir / "imu.csv").string();
  const auto error_of = [&](const std::vector<ImuReading>& readings) {
    test::write_text(dir / "imu.csv", imu_text(readings));
    try {
      read_imu_csv(file);
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string force = error_of({imu_reading(0, 9.81, 0.0), imu_reading(5000, 1.5e6, 0.0)});
  EXPECT_NE(force.find(file + ":3"), std::string::npos) << force;
  EXPECT_NE(force.find("a_z_mps2"), std::string::npos) << force;
  EXPECT_NE(force.find("at most 1e+06 m/s^2"), std::string::npos) << force;
  const std::string turn = error_of({imu_reading(0, 9.81, -2e6)});
  EXPECT_NE(turn.find(file + ":2"), std::string::npos) << turn;
  EXPECT_NE(turn.find("w_x_radps"), std::string::npos) << turn;
}

}  // namespace
}  // namespace wifislam
