// Depth files follow the TUM convention: 16-bit PNG, 5000 units per metre, 0 = no reading.

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>

#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "sim/render/depth_png.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

TEST(DepthPng, RoundTripsAtFiveThousandUnitsPerMetre) {
  cv::Mat depth(2, 3, CV_32FC1);
  depth.at<float>(0, 0) = 1.0f;      // 5000 units
  depth.at<float>(0, 1) = 0.0f;      // no reading
  depth.at<float>(0, 2) = 3.25021f;  // rounds to 16251
  depth.at<float>(1, 0) = 13.107f;   // the largest depth that fits: 65535
  depth.at<float>(1, 1) = 14.0f;     // does not fit: no reading rather than a wrong one
  depth.at<float>(1, 2) = -1.0f;     // invalid
  const fs::path path = test::scratch_folder() / "depth.png";
  render::write_depth_png(path, depth);
  const cv::Mat raw = read_png(path);
  ASSERT_EQ(raw.type(), CV_16UC1);
  EXPECT_EQ(raw.at<std::uint16_t>(0, 0), 5000);
  EXPECT_EQ(raw.at<std::uint16_t>(0, 1), 0);
  EXPECT_EQ(raw.at<std::uint16_t>(0, 2), 16251);
  EXPECT_EQ(raw.at<std::uint16_t>(1, 0), 65535);
  EXPECT_EQ(raw.at<std::uint16_t>(1, 1), 0);
  EXPECT_EQ(raw.at<std::uint16_t>(1, 2), 0);
  const cv::Mat back = render::read_depth_png(path);
  EXPECT_FLOAT_EQ(back.at<float>(0, 2), 3.2502f);  // 16251 / 5000
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
  fs::remove(path);
}

TEST(DepthPng, ReadingAColourImageAsDepthIsAClearError) {
  const fs::path path = test::scratch_folder() / "colour.png";
  render::write_color_png(path, cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)));
  try {
    render::read_depth_png(path);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("16-bit"), std::string::npos) << e.what();
  }
  EXPECT_THROW(render::read_depth_png(path.string() + ".missing"), IoError);
  fs::remove(path);
}

TEST(DepthPng, FalseColourIsBlackWithoutReadingAndDiffersNearToFar) {
  cv::Mat depth(1, 3, CV_32FC1);
  depth.at<float>(0, 0) = 0.0f;
  depth.at<float>(0, 1) = 0.9f;
  depth.at<float>(0, 2) = 3.9f;
  const cv::Mat colour = render::depth_false_color(depth, 0.8, 4.0);
  ASSERT_EQ(colour.type(), CV_8UC3);
  EXPECT_EQ(colour.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  const cv::Vec3b near = colour.at<cv::Vec3b>(0, 1), far = colour.at<cv::Vec3b>(0, 2);
  EXPECT_GT(near[2], near[0]);  // near is red
  EXPECT_GT(far[0], far[2]);    // far is blue
}

}  // namespace
}  // namespace wifislam::sim
