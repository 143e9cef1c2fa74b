// Writing datasets: determinism across runs and thread counts, the round trip through the
// reader, the TUM association convention, the --no-images mode, the pause-and-scan protocol and
// the time origin (Unix stamps that change nothing else).
#include "sim/generate/dataset_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include "core/dataset_calibration.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/imu_csv.hpp"
#include "core/imu_groundtruth_csv.hpp"
#include "core/png_codec.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "core/wifi_csv.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/generator_stream.hpp"
#include "sim/robot/imu_model.hpp"
#include "tests/sim/generate/test_scene.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

generate::GenerateOptions short_run(int threads) {
  generate::GenerateOptions o;
  o.max_frames = 30;
  o.fps = 5.0;  // 6 s: the first pause (two scans) and a little driving
  o.threads = threads;
  return o;
}

TEST(GenerateDataset, SameSeedGivesIdenticalDatasetsWhateverTheThreadCount) {
  const scene::Scene scene = test::small_scene();
  const fs::path a = test::fresh_folder("a"), b = test::fresh_folder("b"),
                 c = test::fresh_folder("c"), d = test::fresh_folder("d");
  const generate::GenerateSummary sa = generate::generate_dataset(scene, a, short_run(1));
  generate::generate_dataset(scene, b, short_run(1));
  const generate::GenerateSummary sc = generate::generate_dataset(scene, c, short_run(2));
  EXPECT_EQ(sa.frames, 30);
  EXPECT_EQ(sc.threads, 2);
  const std::string manifest = test::read_file(a / dataset::kManifest);
  EXPECT_FALSE(manifest.empty());
  EXPECT_EQ(manifest, test::read_file(b / dataset::kManifest));
  EXPECT_EQ(manifest, test::read_file(c / dataset::kManifest));
  // The manifest covers the images through images.sha256; check that too.
  EXPECT_EQ(test::read_file(a / dataset::kImageChecksums),
            test::read_file(c / dataset::kImageChecksums));
  generate::GenerateOptions other_seed = short_run(2);
  other_seed.seed = 78;
  generate::generate_dataset(scene, d, other_seed);
  EXPECT_NE(manifest, test::read_file(d / dataset::kManifest));
  for (const auto& dir : {a, b, c, d}) {
    EXPECT_FALSE(fs::exists(dir.string() + ".partial"));
    fs::remove_all(dir);
  }
}

TEST(GenerateDataset, WrittenDatasetReadsBackEqualToTheInMemoryStream) {
  const scene::Scene scene = test::small_scene();
  const fs::path dir = test::fresh_folder("roundtrip");
  generate::GenerateOptions options = short_run(2);
  generate::generate_dataset(scene, dir, options);

  DatasetReader reader(dir);
  generate::GeneratorStream stream(scene, options);
  EXPECT_TRUE(reader.has_wifi());
  EXPECT_TRUE(reader.has_odometry());
  EXPECT_EQ(reader.intrinsics(), stream.intrinsics());
  EXPECT_TRUE(reader.camera_in_base().isApprox(stream.camera_in_base(), 1e-15));
  const Trajectory ground_truth = read_ground_truth(dir);
  ASSERT_EQ(ground_truth.size(), 30u);

  std::size_t frames = 0, scans = 0, odometry = 0;
  while (true) {
    auto from_disk = reader.next();
    auto from_memory = stream.next();
    ASSERT_EQ(from_disk.has_value(), from_memory.has_value());
    if (!from_disk) break;
    ASSERT_EQ(from_disk->index(), from_memory->index());
    ASSERT_EQ(event_time(*from_disk), event_time(*from_memory));
    if (auto* f = std::get_if<RgbdFrame>(&*from_disk)) {
      const auto& m = std::get<RgbdFrame>(*from_memory);
      EXPECT_EQ(f->index, m.index);
      EXPECT_EQ(f->rgb_path, dataset::frame_image_path(dataset::kRgbDir, f->time));
      EXPECT_EQ(f->depth_path, dataset::frame_image_path(dataset::kDepthDir, f->time));
      EXPECT_EQ(cv::norm(f->rgb, m.rgb, cv::NORM_INF), 0.0);
      EXPECT_EQ(cv::norm(f->depth_m, m.depth_m, cv::NORM_INF), 0.0);
      EXPECT_GT(cv::countNonZero(f->depth_m), f->depth_m.total() / 2);
      const StampedPose& gt = ground_truth[frames];
      EXPECT_EQ(gt.time, f->time);
      EXPECT_TRUE(gt.pose().isApprox(stream.last_frame_ground_truth(), 1e-12));
      ++frames;
    } else if (auto* s = std::get_if<WifiScan>(&*from_disk)) {
      EXPECT_EQ(*s, std::get<WifiScan>(*from_memory));
      EXPECT_GT(s->readings.size(), 0u);
      ++scans;
    } else {
      const auto& o = std::get<OdometryReading>(*from_disk);
      EXPECT_TRUE(
          o.base_in_odom.isApprox(std::get<OdometryReading>(*from_memory).base_in_odom, 1e-12));
      ++odometry;
    }
  }
  EXPECT_EQ(frames, 30u);
  // The run ends with frame 29 at 5.8 s, inside the first 6 s pause: sweeps of 2 s every 2 s end
  // at 2 and 4 s; the one ending at 6 s is past the end.
  EXPECT_EQ(scans, 2u);
  EXPECT_GT(odometry, 250u);
  fs::remove_all(dir);
}

// The sensor parts that are off by default (lateral depth noise, colour noise, auto-exposure):
// switched on, the frames still depend only on the scene and seed (auto-exposure carries state
// from frame to frame, and the pipeline makes frames in order), and only the images move.
TEST(GenerateDataset, SensorNoisePartsAreDeterministicAndMoveOnlyTheImages) {
  const scene::Scene plain = test::small_scene();
  scene::Scene noisy = plain;
  noisy.sensors.depth.lateral_noise = true;
  noisy.sensors.color.noise = true;
  noisy.sensors.color.auto_exposure = true;
  generate::GeneratorStream a(noisy, short_run(1)), b(noisy, short_run(1)),
      off(plain, short_run(1));
  std::size_t frames = 0;
  double rgb_moved = 0.0, depth_moved = 0.0;
  while (true) {
    auto ea = a.next(), eb = b.next(), eo = off.next();
    ASSERT_EQ(ea.has_value(), eo.has_value());
    ASSERT_EQ(ea.has_value(), eb.has_value());
    if (!ea) break;
    ASSERT_EQ(event_time(*ea), event_time(*eo));
    if (auto* fa = std::get_if<RgbdFrame>(&*ea)) {
      const auto& fb = std::get<RgbdFrame>(*eb);
      const auto& fo = std::get<RgbdFrame>(*eo);
      EXPECT_EQ(cv::norm(fa->rgb, fb.rgb, cv::NORM_INF), 0.0) << "frame " << fa->index;
      EXPECT_EQ(cv::norm(fa->depth_m, fb.depth_m, cv::NORM_INF), 0.0) << "frame " << fa->index;
      rgb_moved = std::max(rgb_moved, cv::norm(fa->rgb, fo.rgb, cv::NORM_INF));
      depth_moved = std::max(depth_moved, cv::norm(fa->depth_m, fo.depth_m, cv::NORM_INF));
      ++frames;
    } else if (auto* sa = std::get_if<WifiScan>(&*ea)) {
      EXPECT_EQ(*sa, std::get<WifiScan>(*eo));
    }
  }
  EXPECT_EQ(frames, 30u);
  EXPECT_GT(rgb_moved, 0.0);
  EXPECT_GT(depth_moved, 0.0);
}

// A rewound stream simulates again on the same site: the seed and fps overrides still hold, and
// state carried from frame to frame (auto-exposure, the scanner's randomness) starts afresh.
TEST(GenerateDataset, ARewoundStreamGivesTheEventsOfAFreshOne) {
  scene::Scene scene = test::small_scene();
  scene.sensors.color.auto_exposure = true;
  generate::GenerateOptions options = short_run(1);
  options.seed = 78;
  generate::GeneratorStream rewound(scene, options), fresh(scene, options);
  for (int i = 0; i < 40; ++i) ASSERT_TRUE(rewound.next().has_value());
  rewound.rewind();
  std::size_t frames = 0, scans = 0;
  while (true) {
    auto a = rewound.next(), b = fresh.next();
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a) break;
    ASSERT_EQ(a->index(), b->index());
    ASSERT_EQ(event_time(*a), event_time(*b));
    if (auto* fa = std::get_if<RgbdFrame>(&*a)) {
      const auto& fb = std::get<RgbdFrame>(*b);
      EXPECT_EQ(cv::norm(fa->rgb, fb.rgb, cv::NORM_INF), 0.0) << "frame " << fa->index;
      EXPECT_EQ(cv::norm(fa->depth_m, fb.depth_m, cv::NORM_INF), 0.0) << "frame " << fa->index;
      EXPECT_TRUE(rewound.last_frame_ground_truth().isApprox(fresh.last_frame_ground_truth(), 0.0));
      ++frames;
    } else if (auto* sa = std::get_if<WifiScan>(&*a)) {
      EXPECT_EQ(*sa, std::get<WifiScan>(*b));
      ++scans;
    }
  }
  EXPECT_EQ(frames, 30u);
  EXPECT_EQ(scans, 2u);
  EXPECT_EQ(rewound.pipeline().scene().seed, 78u);
  EXPECT_EQ(rewound.pipeline().scene().sensors.camera.fps, 5.0);
}

TEST(GenerateDataset, AssociationsFollowTheTumAssociateConvention) {
  const fs::path dir = test::fresh_folder("assoc");
  generate::generate_dataset(test::small_scene(), dir, short_run(2));
  const auto rgb = read_tum_file_list((dir / dataset::kRgbList).string());
  const auto depth = read_tum_file_list((dir / dataset::kDepthList).string());
  ASSERT_EQ(rgb.size(), 30u);
  // associate.py on rgb.txt and depth.txt gives exactly associations.txt.
  std::string expected;
  for (const FramePair& p : associate_tum(rgb, depth, 0.02)) expected += format_association_line(p);
  EXPECT_EQ(expected, test::read_file(dir / dataset::kAssociations));
  AssociationsReader reader((dir / dataset::kAssociations).string());
  int pairs = 0;
  while (auto p = reader.next()) {
    EXPECT_LT(std::abs(p->rgb_time.seconds() - p->depth_time.seconds()), 0.02);
    EXPECT_TRUE(fs::exists(dir / p->rgb_path));
    EXPECT_TRUE(fs::exists(dir / p->depth_path));
    ++pairs;
  }
  EXPECT_EQ(pairs, 30);
  // Depth PNGs are TUM's 16-bit format.
  const cv::Mat depth_png = read_png(dir / depth[5].path);
  EXPECT_EQ(depth_png.type(), CV_16UC1);
  fs::remove_all(dir);
}

TEST(GenerateDataset, NoImagesWritesPosesOdometryAndWifiOnly) {
  const fs::path dir = test::fresh_folder("noimg");
  generate::GenerateOptions options;
  options.camera = sim::generate::CameraOutput::kNoImages;
  const generate::GenerateSummary summary =
      generate::generate_dataset(test::small_scene(), dir, options);
  EXPECT_FALSE(fs::exists(dir / dataset::kRgbDir));
  EXPECT_FALSE(fs::exists(dir / dataset::kAssociations));
  EXPECT_GT(summary.frames, 1000);
  DatasetReader reader(dir);
  EXPECT_EQ(reader.frame_count(), 0);
  EXPECT_EQ(reader.wifi_scan_count(), summary.wifi_scans);
  EXPECT_NE(reader.description().find("no images"), std::string::npos) << reader.description();
  EXPECT_EQ(static_cast<std::int64_t>(read_ground_truth(dir).size()), summary.frames);
  fs::remove_all(dir);
}

TEST(GenerateDataset, ScansHappenOnlyWhileTheRobotPauses) {
  const fs::path dir = test::fresh_folder("pauses");
  generate::GenerateOptions options;
  options.camera = sim::generate::CameraOutput::kNoImages;
  const scene::Scene scene = test::small_scene();
  const generate::GenerateSummary summary = generate::generate_dataset(scene, dir, options);
  const generate::GenerationPipeline truth(scene, options);
  const auto& pauses = truth.motion().pauses();
  EXPECT_EQ(summary.pauses, static_cast<std::int64_t>(pauses.size()));
  const auto scans = read_wifi_csv((dir / dataset::kWifi).string());
  ASSERT_EQ(static_cast<std::int64_t>(scans.size()), summary.wifi_scans);
  std::vector<int> scans_per_pause(pauses.size(), 0);
  for (const WifiScan& s : scans) {
    int inside = -1;
    // The file carries Unix stamps; the pauses run on route time.
    for (std::size_t p = 0; p < pauses.size(); ++p)
      if (truth.route_time(s.start_time) >= pauses[p].start &&
          truth.route_time(s.end_time) <= pauses[p].end)
        inside = static_cast<int>(p);
    ASSERT_GE(inside, 0) << "scan at " << s.time.to_string() << " outside every pause";
    ++scans_per_pause[inside];
  }
  for (int n : scans_per_pause) EXPECT_EQ(n, 3);  // 6 s pauses, 2 s sweeps every 2 s
  // Pause spacing within the scene's range.
  for (std::size_t p = 1; p < pauses.size(); ++p) {
    const double gap = pauses[p].arc_length_m - pauses[p - 1].arc_length_m;
    EXPECT_GE(gap, 3.0);
    EXPECT_LE(gap, 4.0);
  }
  EXPECT_GT(summary.aps_heard_per_pause_mean, 0.0);
  EXPECT_LE(summary.aps_heard_per_pause_max, 6);

  // With scan_while_moving the scanner runs throughout.
  scene::Scene moving = scene;
  moving.route.pause.scan_while_moving = true;
  const fs::path dir2 = test::fresh_folder("moving");
  generate::generate_dataset(moving, dir2, options);
  int while_moving = 0;
  for (const WifiScan& s : read_wifi_csv((dir2 / dataset::kWifi).string()))
    while_moving += truth.motion().state_at(truth.route_time(s.start_time)).speed_mps > 0.0;
  EXPECT_GT(while_moving, 5);
  fs::remove_all(dir);
  fs::remove_all(dir2);
}

/// The lines of a text file without '#' comments, each split at its first space: (time, rest).
std::vector<std::pair<Timestamp, std::string>> stamped_lines(const fs::path& file,
                                                             char separator = ' ') {
  std::vector<std::pair<Timestamp, std::string>> out;
  std::istringstream in(test::read_file(file));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line.starts_with("timestamp")) continue;
    const auto cut = line.find(separator);
    const auto t = Timestamp::parse(line.substr(0, cut));
    EXPECT_TRUE(t.has_value()) << file << ": " << line;
    out.emplace_back(t.value_or(Timestamp{}), line.substr(cut + 1));
  }
  return out;
}

// Every stamp a dataset holds is route time plus the scene's sensors.time_origin_s, exactly; the
// origin changes nothing else (images, poses, odometry, RSSI are those of origin 0).
TEST(GenerateDataset, EveryStampIsRouteTimePlusTheSceneTimeOrigin) {
  const scene::Scene scene = test::small_scene();
  EXPECT_EQ(scene.sensors.time_origin_s, 1'700'000'000u);  // the default
  scene::Scene at_zero = scene, overridden = scene;
  at_zero.sensors.time_origin_s = 0;
  overridden.sensors.time_origin_s = 1'234'567'890;
  const fs::path d0 = test::fresh_folder("origin0"), dd = test::fresh_folder("origin_default"),
                 d1 = test::fresh_folder("origin_override");
  generate::generate_dataset(at_zero, d0, short_run(2));
  const generate::GenerateSummary summary = generate::generate_dataset(scene, dd, short_run(2));
  generate::generate_dataset(overridden, d1, short_run(2));
  EXPECT_EQ(summary.time_origin_s, 1'700'000'000u);
  EXPECT_EQ(summary.first_time, Timestamp::from_ns(1'700'000'000'000'000'000LL));

  for (const auto& [dir, origin_s] :
       {std::pair{dd, std::int64_t{1'700'000'000}}, std::pair{d1, std::int64_t{1'234'567'890}}}) {
    const std::int64_t origin_ns = origin_s * 1'000'000'000;
    for (const char* file : {dataset::kRgbList, dataset::kDepthList, dataset::kGroundTruth,
                             dataset::kOdometry, dataset::kAssociations}) {
      const auto zero = stamped_lines(d0 / file), shifted = stamped_lines(dir / file);
      ASSERT_EQ(zero.size(), shifted.size()) << file;
      ASSERT_FALSE(zero.empty()) << file;
      EXPECT_EQ(shifted.front().first.ns, origin_ns) << file << ": the route starts at the origin";
      for (std::size_t i = 0; i < zero.size(); ++i) {
        EXPECT_EQ(shifted[i].first.ns - zero[i].first.ns, origin_ns) << file << " line " << i;
        if (std::string(file) == dataset::kGroundTruth || std::string(file) == dataset::kOdometry) {
          EXPECT_EQ(shifted[i].second, zero[i].second) << file << ": poses moved";
        }
      }
    }
    // Image names are the stamps.
    for (const FramePair& p : read_frame_pairs(dir)) {
      EXPECT_EQ(p.rgb_path, "rgb/" + p.rgb_time.to_string(6) + ".png");
      EXPECT_TRUE(fs::exists(dir / p.rgb_path)) << p.rgb_path;
    }
    const auto scans0 = read_wifi_csv((d0 / dataset::kWifi).string());
    auto scans = read_wifi_csv((dir / dataset::kWifi).string());
    ASSERT_EQ(scans.size(), scans0.size());
    ASSERT_FALSE(scans.empty());
    for (std::size_t i = 0; i < scans.size(); ++i) {
      for (Timestamp* t : {&scans[i].time, &scans[i].start_time, &scans[i].end_time}) {
        t->ns -= origin_ns;
      }
      EXPECT_EQ(scans[i], scans0[i]) << "scan " << i;  // same readings, shifted stamps
    }
    // The pixels are the same; only the names in images.sha256 differ.
    std::istringstream a(test::read_file(d0 / dataset::kImageChecksums)),
        b(test::read_file(dir / dataset::kImageChecksums));
    std::string line_a, line_b;
    while (std::getline(a, line_a) && std::getline(b, line_b)) {
      EXPECT_EQ(line_a.substr(0, 64), line_b.substr(0, 64));
    }
    const auto manifest = nlohmann::json::parse(test::read_file(dir / dataset::kManifest));
    EXPECT_EQ(manifest.at("parameters").at("time_origin_s"), origin_s) << manifest.dump();
    EXPECT_NE(
        test::read_file(dir / dataset::kScene).find("time_origin_s: " + std::to_string(origin_s)),
        std::string::npos);
  }
  for (const auto& dir : {d0, dd, d1}) fs::remove_all(dir);
}

TEST(GenerateDataset, ImuCsvHoldsEverySampleOfTheRunAndCalibrationDescribesTheImu) {
  const scene::Scene scene = test::small_scene();
  const fs::path dir = test::fresh_folder("imu");
  const generate::GenerateSummary summary = generate::generate_dataset(scene, dir, short_run(2));
  const std::vector<ImuReading> imu = read_imu_csv((dir / dataset::kImu).string());
  // 200 Hz over the run (30 frames at 5 fps: its end is the last frame's time).
  ASSERT_EQ(static_cast<std::int64_t>(imu.size()), summary.imu_samples);
  const double run_s = summary.last_time.seconds() - summary.first_time.seconds();
  EXPECT_EQ(summary.imu_samples, static_cast<std::int64_t>(std::floor(run_s * 200.0)) + 1);
  EXPECT_EQ(imu.front().time, summary.first_time);  // the time origin, as every stamp
  for (std::size_t i = 1; i < imu.size(); ++i)
    ASSERT_EQ(imu[i].time.ns - imu[i - 1].time.ns, 5'000'000) << "row " << i;
  // The robot stands through its first pause: gravity up, within the noise (sigma ~0.03 m/s^2
  // white at 200 Hz, plus the bias walk).
  const ImuReading& first = imu.front();
  EXPECT_NEAR(first.specific_force_mps2.z(), robot::kStandardGravityMps2, 0.2);
  EXPECT_NEAR(first.specific_force_mps2.head<2>().norm(), 0.0, 0.2);
  const auto manifest = nlohmann::json::parse(test::read_file(dir / dataset::kManifest));
  EXPECT_EQ(manifest.at("counts").at("imu_samples"), summary.imu_samples);

  const DatasetCalibration calibration = read_calibration_yaml(dir / dataset::kCalibration);
  ASSERT_TRUE(calibration.imu.has_value());
  EXPECT_EQ(calibration.imu->rate_hz, 200.0);
  EXPECT_EQ(calibration.imu->gyroscope_noise_density, scene.sensors.imu.gyroscope_noise_density);
  EXPECT_EQ(calibration.imu->accelerometer_random_walk,
            scene.sensors.imu.accelerometer_random_walk);
  // T_cam_imu takes the IMU's origin to where the camera sees it: below the camera (optical y
  // points down) by the camera's height above the IMU.
  const Eigen::Vector3d imu_in_camera = calibration.camera_from_imu().translation();
  EXPECT_NEAR(imu_in_camera.y(), scene.sensors.camera.height_m - scene.sensors.imu.position_m.z(),
              1e-12);

  // The IMU's true state at every frame time: the camera's ground truth carried to the IMU by
  // the calibration's T_cam_imu.
  const std::vector<ImuGroundTruth> truth =
      read_imu_groundtruth_csv((dir / dataset::kImuGroundTruth).string());
  const Trajectory camera = read_tum_trajectory((dir / dataset::kGroundTruth).string());
  ASSERT_EQ(truth.size(), camera.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_EQ(truth[i].time, camera[i].time);
    const Pose expected = camera[i].pose() * calibration.camera_from_imu();
    EXPECT_LT((truth[i].imu_to_world.matrix() - expected.matrix()).norm(), 1e-9) << "frame " << i;
  }

  scene::Scene without = scene;
  without.sensors.imu.enabled = false;
  const fs::path none = test::fresh_folder("no_imu");
  generate::generate_dataset(without, none, short_run(2));
  EXPECT_FALSE(fs::exists(none / dataset::kImu));
  EXPECT_FALSE(fs::exists(none / dataset::kImuGroundTruth));
  EXPECT_FALSE(read_calibration_yaml(none / dataset::kCalibration).imu.has_value());
  // Nothing else moves: the IMU draws from its own stream.
  for (const char* file : {dataset::kGroundTruth, dataset::kOdometry, dataset::kWifi})
    EXPECT_EQ(test::read_file(dir / file), test::read_file(none / file)) << file;
  EXPECT_EQ(test::read_file(dir / dataset::kImageChecksums),
            test::read_file(none / dataset::kImageChecksums));
  fs::remove_all(dir);
  fs::remove_all(none);
}

}  // namespace
}  // namespace wifislam::sim
