// Writing datasets: determinism across runs and thread counts, the round trip through the
// reader, the TUM association convention, the --no-images mode and the pause-and-scan protocol.
#include "sim/generate/dataset_writer.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/tum_file_list.hpp"
#include "core/wifi_csv.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/generator_stream.hpp"
#include "tests/generate/test_scene.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

GenerateOptions short_run(int threads) {
  GenerateOptions o;
  o.max_frames = 30;
  o.fps = 5.0;  // 6 s: the first pause (two scans) and a little driving
  o.threads = threads;
  return o;
}

TEST(GenerateDataset, SameSeedGivesIdenticalDatasetsWhateverTheThreadCount) {
  const Scene scene = test::small_scene();
  const fs::path a = test::fresh_folder("a"), b = test::fresh_folder("b"),
                 c = test::fresh_folder("c"), d = test::fresh_folder("d");
  const GenerateSummary sa = generate_dataset(scene, a, short_run(1));
  generate_dataset(scene, b, short_run(1));
  const GenerateSummary sc = generate_dataset(scene, c, short_run(2));
  EXPECT_EQ(sa.frames, 30);
  EXPECT_EQ(sc.threads, 2);
  const std::string manifest = test::read_text(a / dataset::kManifest);
  EXPECT_FALSE(manifest.empty());
  EXPECT_EQ(manifest, test::read_text(b / dataset::kManifest));
  EXPECT_EQ(manifest, test::read_text(c / dataset::kManifest));
  // The manifest covers the images through images.sha256; check that too.
  EXPECT_EQ(test::read_text(a / dataset::kImageChecksums),
            test::read_text(c / dataset::kImageChecksums));
  GenerateOptions other_seed = short_run(2);
  other_seed.seed = 78;
  generate_dataset(scene, d, other_seed);
  EXPECT_NE(manifest, test::read_text(d / dataset::kManifest));
  for (const auto& dir : {a, b, c, d}) {
    EXPECT_FALSE(fs::exists(dir.string() + ".partial"));
    fs::remove_all(dir);
  }
}

TEST(GenerateDataset, WrittenDatasetReadsBackEqualToTheInMemoryStream) {
  const Scene scene = test::small_scene();
  const fs::path dir = test::fresh_folder("roundtrip");
  GenerateOptions options = short_run(2);
  generate_dataset(scene, dir, options);

  DatasetReader reader(dir);
  GeneratorStream stream(scene, options);
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

TEST(GenerateDataset, AssociationsFollowTheTumAssociateConvention) {
  const fs::path dir = test::fresh_folder("assoc");
  generate_dataset(test::small_scene(), dir, short_run(2));
  const auto rgb = read_tum_file_list((dir / dataset::kRgbList).string());
  const auto depth = read_tum_file_list((dir / dataset::kDepthList).string());
  ASSERT_EQ(rgb.size(), 30u);
  // associate.py on rgb.txt and depth.txt gives exactly associations.txt.
  std::string expected;
  for (const FramePair& p : associate_tum(rgb, depth, 0.02)) expected += format_association_line(p);
  EXPECT_EQ(expected, test::read_text(dir / dataset::kAssociations));
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
  const cv::Mat depth_png = cv::imread((dir / depth[5].path).string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(depth_png.type(), CV_16UC1);
  fs::remove_all(dir);
}

TEST(GenerateDataset, NoImagesWritesPosesOdometryAndWifiOnly) {
  const fs::path dir = test::fresh_folder("noimg");
  GenerateOptions options;
  options.images = false;
  const GenerateSummary summary = generate_dataset(test::small_scene(), dir, options);
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
  GenerateOptions options;
  options.images = false;
  const Scene scene = test::small_scene();
  const GenerateSummary summary = generate_dataset(scene, dir, options);
  const GenerationPipeline truth(scene, options);
  const auto& pauses = truth.motion().pauses();
  EXPECT_EQ(summary.pauses, static_cast<std::int64_t>(pauses.size()));
  const auto scans = read_wifi_csv((dir / dataset::kWifi).string());
  ASSERT_EQ(static_cast<std::int64_t>(scans.size()), summary.wifi_scans);
  std::vector<int> scans_per_pause(pauses.size(), 0);
  for (const WifiScan& s : scans) {
    int inside = -1;
    for (std::size_t p = 0; p < pauses.size(); ++p)
      if (s.start_time >= pauses[p].start && s.end_time <= pauses[p].end)
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
  Scene moving = scene;
  moving.route.pause.scan_while_moving = true;
  const fs::path dir2 = test::fresh_folder("moving");
  generate_dataset(moving, dir2, options);
  int while_moving = 0;
  for (const WifiScan& s : read_wifi_csv((dir2 / dataset::kWifi).string()))
    while_moving += truth.motion().state_at(s.start_time).speed_mps > 0.0;
  EXPECT_GT(while_moving, 5);
  fs::remove_all(dir);
  fs::remove_all(dir2);
}

}  // namespace
}  // namespace wifislam
