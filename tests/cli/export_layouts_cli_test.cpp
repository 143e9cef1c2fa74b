// `wifislam export --for euroc|kapture` (rosbag: tests/interop/rosbag_export_test.py), read back by
// each format's documented rules (neither has a reader Debian packages): EuRoC's ASL folder
// (data.csv headers and nanosecond stamps, links to the dataset's own images, imu0 equal to
// imu.csv, the ground truth equal to imu_groundtruth.csv, sensor.yaml's T_BS the inverse of
// T_cam_imu) and Kapture 1.1 (the version line, field counts, device ids declared in sensors.txt,
// world-to-rig poses that invert to the ground truth, .depth files equal to the depth PNGs in
// metres, one Wi-Fi row per reading); refusals are exit 2 with nothing written.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/dataset_calibration.hpp"
#include "core/dataset_reader.hpp"
#include "core/imu_csv.hpp"
#include "core/imu_groundtruth_csv.hpp"
#include "core/png_codec.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "core/wifi_csv.hpp"
#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::read_file;

/// Non-comment lines of a text file, split on commas with the spaces around them trimmed.
std::vector<std::vector<std::string>> csv_lines(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(test::read_file(file));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream fields_in(line);
    std::string field;
    while (std::getline(fields_in, field, ',')) {
      const auto b = field.find_first_not_of(' '), e = field.find_last_not_of(' ');
      fields.push_back(b == std::string::npos ? "" : field.substr(b, e - b + 1));
    }
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

double number(const std::string& text) {
  std::size_t used = 0;
  const double v = std::stod(text, &used);
  EXPECT_EQ(used, text.size()) << text;
  return v;
}

class ExportLayoutsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = test::shared_tiny_wifi_dataset();
    no_imu_ = test::shared_dataset(
        test::tiny_loop_yaml_with("radio: {environment: office}",
                                  "radio: {environment: office}\nsensors: {imu: {enabled: false}}"),
        "--fps 2 --max-frames 4");
    generated_ = !dataset_.empty() && !no_imu_.empty();
  }
  void SetUp() override {
    ASSERT_TRUE(generated_);
    scratch_ = test::scratch_folder();
  }
  void TearDown() override { fs::remove_all(scratch_); }

  static fs::path dataset() { return dataset_; }
  test::CliResult export_to(const fs::path& data, const std::string& layout, const fs::path& out,
                            const std::string& extra_args = "") {
    return test::run_wifislam(
        "export " + data.string() + " --for " + layout + " -o " + out.string() + " " + extra_args,
        scratch_);
  }

  static inline fs::path dataset_, no_imu_;
  static inline bool generated_ = false;
  fs::path scratch_;
};

TEST_F(ExportLayoutsCli, EurocLayoutHoldsTheFramesTheImuAndItsGroundTruthInNanoseconds) {
  const fs::path out = scratch_ / "euroc";
  const auto r = export_to(dataset(), "euroc", out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path mav = out / "mav0";

  const std::vector<FramePair> pairs = read_frame_pairs(dataset());
  for (const char* sensor : {"cam0", "depth0"}) {
    const std::string csv = test::read_file(mav / sensor / "data.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "#timestamp [ns],filename") << sensor;
    const auto rows = csv_lines(mav / sensor / "data.csv");
    ASSERT_EQ(rows.size(), pairs.size()) << sensor;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      ASSERT_EQ(rows[i].size(), 2u);
      EXPECT_EQ(rows[i][0], std::to_string(pairs[i].rgb_time.ns));
      EXPECT_EQ(rows[i][1], rows[i][0] + ".png");
      const fs::path image = mav / sensor / "data" / rows[i][1];
      ASSERT_TRUE(fs::is_symlink(image)) << image;
      const std::string& source =
          std::string(sensor) == "cam0" ? pairs[i].rgb_path : pairs[i].depth_path;
      EXPECT_EQ(fs::canonical(image), fs::canonical(dataset() / source));
    }
  }
  EXPECT_EQ(csv_lines(out / "timestamps.txt").size(), pairs.size());

  // imu0 is imu.csv, in nanoseconds.
  const std::vector<ImuReading> imu = read_imu_csv((dataset() / "imu.csv").string());
  const std::string imu_csv = test::read_file(mav / "imu0/data.csv");
  EXPECT_EQ(imu_csv.substr(0, imu_csv.find('\n')),
            "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
            "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]");
  const auto imu_rows = csv_lines(mav / "imu0/data.csv");
  ASSERT_EQ(imu_rows.size(), imu.size());
  ASSERT_GT(imu.size(), 1000u);  // 200 Hz over the route
  for (std::size_t i = 0; i < imu.size(); i += 97) {
    ASSERT_EQ(imu_rows[i].size(), 7u);
    EXPECT_EQ(imu_rows[i][0], std::to_string(imu[i].time.ns));
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(number(imu_rows[i][1 + a]), imu[i].angular_velocity_radps[a]);
      EXPECT_EQ(number(imu_rows[i][4 + a]), imu[i].specific_force_mps2[a]);
    }
  }

  // The ground truth: 17 columns, EuRoC's order (w first), equal to imu_groundtruth.csv.
  const std::vector<ImuGroundTruth> truth =
      read_imu_groundtruth_csv((dataset() / "imu_groundtruth.csv").string());
  const auto truth_rows = csv_lines(mav / "state_groundtruth_estimate0/data.csv");
  ASSERT_EQ(truth_rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    ASSERT_EQ(truth_rows[i].size(), 17u);
    EXPECT_EQ(truth_rows[i][0], std::to_string(truth[i].time.ns));
    const Eigen::Quaterniond q(truth[i].imu_to_world.linear());
    EXPECT_EQ(number(truth_rows[i][4]), q.w());
    EXPECT_EQ(number(truth_rows[i][1]), truth[i].imu_to_world.translation().x());
    EXPECT_EQ(number(truth_rows[i][8]), truth[i].velocity_mps.x());
  }

  // sensor.yaml: cam0 in the body (IMU) frame is the inverse of T_cam_imu; imu0 carries the noise.
  const DatasetCalibration calibration = read_calibration_yaml(dataset() / "calibration.yaml");
  const YAML::Node cam = YAML::LoadFile((mav / "cam0/sensor.yaml").string());
  const auto data = cam["T_BS"]["data"].as<std::vector<double>>();
  ASSERT_EQ(data.size(), 16u);
  Eigen::Matrix4d t_bs;
  for (int i = 0; i < 16; ++i) t_bs(i / 4, i % 4) = data[i];
  EXPECT_LT((t_bs * calibration.camera_from_imu().matrix() - Eigen::Matrix4d::Identity()).norm(),
            1e-12);
  const auto intrinsics = cam["intrinsics"].as<std::vector<double>>();
  EXPECT_EQ(intrinsics,
            (std::vector<double>{calibration.intrinsics.fx_px, calibration.intrinsics.fy_px,
                                 calibration.intrinsics.cx_px, calibration.intrinsics.cy_px}));
  const YAML::Node imu_yaml = YAML::LoadFile((mav / "imu0/sensor.yaml").string());
  EXPECT_EQ(imu_yaml["rate_hz"].as<double>(), 200.0);
  EXPECT_EQ(imu_yaml["gyroscope_noise_density"].as<double>(),
            calibration.imu->gyroscope_noise_density);
  EXPECT_EQ(imu_yaml["accelerometer_random_walk"].as<double>(),
            calibration.imu->accelerometer_random_walk);
  const YAML::Node depth_yaml = YAML::LoadFile((mav / "depth0/sensor.yaml").string());
  EXPECT_EQ(depth_yaml["depth_map_factor"].as<double>(), 5000.0);
}

TEST_F(ExportLayoutsCli, EurocRefusesADatasetWithoutAnImuAndWritesNothing) {
  const fs::path out = scratch_ / "euroc";
  const auto r = export_to(no_imu_, "euroc", out);
  test::expect_located_bad_input(r, no_imu_.string(), "has no IMU");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(scratch_ / "euroc.partial"));
}

TEST_F(ExportLayoutsCli, KaptureFolderFollowsTheFormatsRulesAndCarriesWifiDepthAndImu) {
  const fs::path out = scratch_ / "kapture";
  const auto r = export_to(dataset(), "kapture", out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path sensors = out / "sensors";

  // Every text file starts with the version line; rows have the documented field counts.
  const std::map<std::string, std::size_t> fields = {{"rigs.txt", 9},
                                                     {"trajectories.txt", 9},
                                                     {"records_camera.txt", 3},
                                                     {"records_depth.txt", 3},
                                                     {"records_wifi.txt", 8},
                                                     {"records_accelerometer.txt", 5},
                                                     {"records_gyroscope.txt", 5}};
  for (const auto& e : fs::directory_iterator(sensors)) {
    if (e.path().extension() != ".txt") continue;
    const std::string text = test::read_file(e.path());
    EXPECT_EQ(text.substr(0, text.find('\n')), "# kapture format: 1.1") << e.path();
    const std::string name = e.path().filename().string();
    if (fields.count(name) == 0) continue;
    for (const auto& row : csv_lines(e.path())) EXPECT_EQ(row.size(), fields.at(name)) << name;
  }

  // sensors.txt declares every device a record names; rigs are not sensors.
  std::map<std::string, std::vector<std::string>> declared;
  for (const auto& row : csv_lines(sensors / "sensors.txt")) declared[row[0]] = row;
  EXPECT_EQ(declared.at("cam0")[2], "camera");
  EXPECT_EQ(declared.at("depth0")[2], "depth");
  EXPECT_EQ(declared.at("wifi0")[2], "wifi");
  EXPECT_EQ(declared.at("accel0")[2], "accelerometer");
  EXPECT_EQ(declared.at("gyro0")[2], "gyroscope");
  const DatasetCalibration calibration = read_calibration_yaml(dataset() / "calibration.yaml");
  const CameraIntrinsics& k = calibration.intrinsics;
  EXPECT_EQ(declared.at("cam0"), (std::vector<std::string>{
                                     "cam0", "rgb", "camera", "PINHOLE", std::to_string(k.width_px),
                                     std::to_string(k.height_px), "525", "525", "319.5", "239.5"}));
  for (const char* file : {"records_camera.txt", "records_depth.txt", "records_wifi.txt",
                           "records_accelerometer.txt", "records_gyroscope.txt"}) {
    for (const auto& row : csv_lines(sensors / file))
      EXPECT_EQ(declared.count(row[1]), 1u) << file << ": " << row[1];
  }
  for (const auto& row : csv_lines(sensors / "rigs.txt")) {
    EXPECT_EQ(declared.count(row[0]), 0u) << row[0];
    EXPECT_EQ(declared.count(row[1]), 1u) << row[1];
  }

  // trajectories.txt: world -> rig, the inverse of the camera's ground truth.
  const Trajectory gt = read_ground_truth(dataset());
  const auto poses = csv_lines(sensors / "trajectories.txt");
  ASSERT_EQ(poses.size(), gt.size());
  for (std::size_t i = 0; i < gt.size(); ++i) {
    EXPECT_EQ(poses[i][0], std::to_string(gt[i].time.ns / 1000));
    const Eigen::Quaterniond q(number(poses[i][2]), number(poses[i][3]), number(poses[i][4]),
                               number(poses[i][5]));
    const Pose world_to_rig = pose_from_translation_quaternion(
        {number(poses[i][6]), number(poses[i][7]), number(poses[i][8])}, q);
    EXPECT_TRUE((world_to_rig * gt[i].pose()).matrix().isIdentity(1e-9)) << "pose " << i;
  }

  // Images are links to the dataset's; depth maps are float32 metres equal to the PNGs'.
  const std::vector<FramePair> pairs = read_frame_pairs(dataset());
  const auto images = csv_lines(sensors / "records_camera.txt");
  const auto depths = csv_lines(sensors / "records_depth.txt");
  ASSERT_EQ(images.size(), pairs.size());
  ASSERT_EQ(depths.size(), pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const fs::path image = sensors / "records_data" / images[i][2];
    EXPECT_EQ(fs::canonical(image), fs::canonical(dataset() / pairs[i].rgb_path));
    const fs::path depth = sensors / "records_data" / depths[i][2];
    ASSERT_EQ(fs::file_size(depth), static_cast<std::uintmax_t>(k.width_px * k.height_px * 4));
    const std::string png = test::read_file(dataset() / pairs[i].depth_path);
    const cv::Mat expected =
        decode_depth_png(std::vector<unsigned char>(png.begin(), png.end()), 5000.0, "png");
    const std::string raw = test::read_file(depth);
    const cv::Mat got(k.height_px, k.width_px, CV_32FC1, const_cast<char*>(raw.data()));
    EXPECT_EQ(cv::norm(got, expected, cv::NORM_INF), 0.0) << depth;
  }

  // One Wi-Fi row per reading of wifi.csv, frequency in MHz, stamps in microseconds.
  const std::vector<WifiScan> scans = read_wifi_csv((dataset() / "wifi.csv").string());
  const auto wifi = csv_lines(sensors / "records_wifi.txt");
  std::size_t row = 0;
  for (const WifiScan& scan : scans) {
    for (const WifiReading& reading : scan.readings) {
      ASSERT_LT(row, wifi.size());
      EXPECT_EQ(wifi[row][0], std::to_string(scan.time.ns / 1000));
      EXPECT_EQ(wifi[row][2], reading.bssid.to_string());
      EXPECT_EQ(wifi[row][3], std::to_string(reading.frequency_khz / 1000));
      EXPECT_EQ(wifi[row][4], std::to_string(reading.rssi_dbm));
      EXPECT_EQ(wifi[row][6], std::to_string(scan.start_time.ns / 1000));
      ++row;
    }
  }
  EXPECT_EQ(row, wifi.size());
  EXPECT_GT(row, 0u);
  EXPECT_EQ(csv_lines(sensors / "records_accelerometer.txt").size(),
            read_imu_csv((dataset() / "imu.csv").string()).size());
}

TEST_F(ExportLayoutsCli, EveryLayoutRefusesAnUnfinishedDatasetAndWritesNothing) {
  // What an interrupted `generate` leaves: the folder without its manifest (written last).
  const fs::path unfinished = scratch_ / "unfinished";
  fs::copy(dataset(), unfinished, fs::copy_options::recursive);
  fs::remove(unfinished / "manifest.json");
  for (const char* layout : {"euroc", "kapture", "rosbag"}) {
    const fs::path out = scratch_ / layout;
    const auto r = export_to(unfinished, layout, out);
    test::expect_located_bad_input(r, unfinished.string(), "unfinished dataset");
    EXPECT_FALSE(fs::exists(out)) << layout;
    EXPECT_FALSE(fs::exists(out.string() + ".partial")) << layout;
  }
}

// An image edited after `generate`: the link layouts never decode images, so they did not check
// them either, and exported the edited dataset as verified; `check --no-images` said "all files
// match". Every layout and `check --no-images` now compare each image with images.sha256, and
// name the file; --no-verify still exports it.
TEST_F(ExportLayoutsCli, AnImageEditedSinceGenerateIsRefusedByEveryLayoutAndByCheck) {
  const fs::path edited = scratch_ / "edited";
  fs::copy(dataset(), edited, fs::copy_options::recursive);
  const std::vector<FramePair> pairs = read_frame_pairs(edited);
  const fs::path image = edited / pairs[pairs.size() / 2].rgb_path;
  std::string bytes = test::read_file(image);
  bytes[bytes.size() / 2] ^= 0x5a;  // one byte of a PNG's data
  fs::remove(image);                // the export's links or the dataset may share the inode
  test::write_file(image, bytes);
  for (const char* layout : {"rtabmap", "orbslam2", "euroc", "kapture", "rosbag"}) {
    const fs::path out = scratch_ / (std::string("edited_") + layout);
    const auto r = export_to(edited, layout, out);
    test::expect_located_bad_input(r, image.string(), "contents differ from");
    EXPECT_FALSE(fs::exists(out)) << layout;
  }
  const auto check = test::run_wifislam("check " + edited.string() + " --no-images", scratch_);
  test::expect_located_bad_input(check, image.string(), "contents differ from");
  const auto unverified =
      test::run_wifislam("export " + edited.string() + " --for kapture --no-verify -q -o " +
                             (scratch_ / "edited_unverified").string(),
                         scratch_);
  EXPECT_EQ(unverified.exit_code, 0) << unverified.err;
}

// wifi.csv names the receiver of each scan (sensor_id). Kapture wrote every scan as wifi0's, so
// two receivers' scans at one instant shared one record key. Each receiver is now a sensor of its
// own; the bag gives each other receiver a topic, and refuses an id no ROS topic can hold.
TEST_F(ExportLayoutsCli, EachWifiReceiverIsASensorOfItsOwn) {
  const std::vector<WifiScan> scans = read_wifi_csv((dataset() / "wifi.csv").string());
  ASSERT_GE(scans.size(), 2u);
  const auto relabelled = [&](const std::string& id) {
    const fs::path edited = scratch_ / ("receiver_" + id);
    fs::copy(dataset(), edited, fs::copy_options::recursive);
    std::string text = wifi_csv_header() + "\n";
    for (std::size_t i = 0; i < scans.size(); ++i) {
      WifiScan scan = scans[i];
      if (i == 1) scan.sensor_id = id;
      text += format_wifi_csv_rows(scan);
    }
    test::write_file(edited / "wifi.csv", text);
    return edited;
  };
  const fs::path two = relabelled("phone_2");
  const fs::path out = scratch_ / "receivers_kapture";
  const auto r = export_to(two, "kapture", out, "--no-verify");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, std::string> type_of;
  for (const auto& row : csv_lines(out / "sensors/sensors.txt")) type_of[row[0]] = row[2];
  EXPECT_EQ(type_of.at("wifi0"), "wifi");
  EXPECT_EQ(type_of.at("phone_2"), "wifi");
  std::set<std::string> rigged;
  for (const auto& row : csv_lines(out / "sensors/rigs.txt")) rigged.insert(row[1]);
  EXPECT_EQ(rigged.count("phone_2"), 1u);
  std::map<std::string, std::size_t> rows_of;
  for (const auto& row : csv_lines(out / "sensors/records_wifi.txt")) ++rows_of[row[1]];
  EXPECT_EQ(rows_of.at("phone_2"), scans[1].readings.size());
  EXPECT_EQ(rows_of.size(), 2u);

  EXPECT_EQ(export_to(two, "rosbag", scratch_ / "receivers_bag", "--no-verify").exit_code, 0);
  const fs::path bad = relabelled("2phone");
  const auto refused = export_to(bad, "rosbag", scratch_ / "bad_receiver_bag", "--no-verify");
  test::expect_located_bad_input(refused, "sensor_id '2phone'", "ROS");
  EXPECT_FALSE(fs::exists(scratch_ / "bad_receiver_bag"));
  EXPECT_FALSE(fs::exists(scratch_ / "bad_receiver_bag.partial"));
  // Kapture: an id that names another of the export's sensors would declare it twice.
  const auto clash =
      export_to(relabelled("cam0"), "kapture", scratch_ / "clash_kapture", "--no-verify");
  test::expect_located_bad_input(clash, "sensor_id 'cam0'", "cannot name a Kapture Wi-Fi sensor");
  EXPECT_FALSE(fs::exists(scratch_ / "clash_kapture"));
}

// `check` never read imu.csv: a dataset it passed was then refused by the exports that carry the
// IMU, and a reading of 1e30 m/s^2 passed both. Both now read it alike, naming row and column.
TEST_F(ExportLayoutsCli, CheckReadsTheImuAsTheExportsDo) {
  const std::string rows = test::read_file(dataset() / "imu.csv");
  const std::size_t line_4 = rows.find('\n', rows.find('\n', rows.find('\n') + 1) + 1) + 1;
  const std::size_t end = rows.find('\n', line_4);
  const std::string row = rows.substr(line_4, end - line_4);
  const std::string last_field = row.substr(row.rfind(',') + 1);
  for (const char* bad : {"nan", "1e30"}) {
    const fs::path edited = scratch_ / (std::string("imu_") + bad);
    fs::copy(dataset(), edited, fs::copy_options::recursive);
    test::write_file(edited / "imu.csv", rows.substr(0, line_4) +
                                             row.substr(0, row.size() - last_field.size()) + bad +
                                             rows.substr(end));
    const std::string where = (edited / "imu.csv").string() + ":4";
    const auto check = test::run_wifislam("check " + edited.string() + " --no-verify", scratch_);
    test::expect_located_bad_input(check, where, "a_z_mps2");
    for (const char* layout : {"euroc", "kapture", "rosbag"}) {
      const fs::path out = scratch_ / (std::string("imu_") + bad + "_" + layout);
      const auto r = test::run_wifislam(
          "export " + edited.string() + " --for " + layout + " --no-verify -q -o " + out.string(),
          scratch_);
      test::expect_located_bad_input(r, where, "a_z_mps2");
      EXPECT_FALSE(fs::exists(out)) << layout;
    }
  }
  const auto intact = test::run_wifislam("check " + dataset().string(), scratch_);
  EXPECT_EQ(intact.exit_code, 0) << intact.err;
  EXPECT_NE(intact.out.find(", imu readings "), std::string::npos) << intact.out;
  EXPECT_NE(intact.out.find(", imu ground truth rows "), std::string::npos) << intact.out;
}

// Kapture's .depth files are raw float32 of the size sensors.txt gives: a depth image of another
// size was written as is (a 320x240 image in a 640x480 dataset), unreadable by kapture. Refused,
// naming the image, even with --no-verify.
TEST_F(ExportLayoutsCli, KaptureRefusesADepthImageOfAnotherSize) {
  const fs::path resized = scratch_ / "resized";
  fs::copy(dataset(), resized, fs::copy_options::recursive);
  const std::vector<FramePair> pairs = read_frame_pairs(resized);
  const fs::path depth = resized / pairs.back().depth_path;
  fs::remove(depth);
  write_png(depth, cv::Mat(240, 320, CV_16UC1, cv::Scalar(5000)));
  const fs::path out = scratch_ / "resized_kapture";
  const auto r = test::run_wifislam(
      "export " + resized.string() + " --for kapture --no-verify -o " + out.string(), scratch_);
  test::expect_located_bad_input(r, depth.string(), "image is 320x240, the calibration says");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ExportLayoutsCli, RosbagRefusesADatasetStartingAtZeroAndWritesNothing) {
  // A bag holds no message at time 0: such a dataset (time_origin_s: 0) is bad input, not an
  // I/O error halfway through the bag.
  const fs::path scene = test::tiny_loop_with(scratch_, "radio: {environment: office}",
                                              "radio: {environment: office}\n"
                                              "sensors: {time_origin_s: 0}",
                                              "origin0.yaml");
  const fs::path data = scratch_ / "origin0";
  ASSERT_EQ(
      test::run_wifislam(
          "generate " + scene.string() + " --fps 2 --max-frames 3 -q -o " + data.string(), scratch_)
          .exit_code,
      0);
  const fs::path out = scratch_ / "bag";
  const auto r = export_to(data, "rosbag", out);
  test::expect_located_bad_input(r, data.string(), "not a positive time");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(scratch_ / "bag.partial"));
}

TEST_F(ExportLayoutsCli, AnUnknownLayoutIsRefused) {
  const auto r = export_to(dataset(), "bagfile", scratch_ / "x");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bagfile"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch_ / "x"));
}

}  // namespace
}  // namespace wifislam
