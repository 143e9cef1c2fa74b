// The dataset reader on folders written by hand in the documented format: a plain TUM RGB-D
// folder and a small wifislam dataset (frames, odometry, Wi-Fi, calibration, manifest).
#include "core/dataset_reader.hpp"

#include <gtest/gtest.h>

#include <regex>

#include <opencv2/core.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "core/wifi_csv.hpp"
#include "tests/core/test_folder.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

// Frame k: colour (k, 2k, 3k) everywhere, depth (k + 1) m in TUM units.
void write_frame_images(const fs::path& dir, Timestamp t, int k, int w, int h) {
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  write_png(dir / dataset::frame_image_path(dataset::kRgbDir, t),
            cv::Mat(h, w, CV_8UC3, cv::Scalar(k, 2 * k, 3 * k)));
  write_png(dir / dataset::frame_image_path(dataset::kDepthDir, t),
            cv::Mat(h, w, CV_16UC1, cv::Scalar((k + 1) * 5000)));
}

Timestamp frame_time(int k) { return Timestamp::from_ns(k * 100'000'000LL); }  // 10 Hz

void write_plain_tum(const fs::path& dir, int frames) {
  std::string rgb = "# color images\n# file: 'plain'\n# timestamp filename\n", depth = rgb;
  for (int k = 0; k < frames; ++k) {
    const Timestamp t = frame_time(k);
    write_frame_images(dir, t, k, 640, 480);
    rgb += format_tum_file_line(t, dataset::frame_image_path(dataset::kRgbDir, t));
    // Depth stamps offset by 3 ms, as real Kinect streams are.
    const Timestamp td = Timestamp::from_ns(t.ns + 3'000'000);
    fs::rename(dir / dataset::frame_image_path(dataset::kDepthDir, t),
               dir / dataset::frame_image_path(dataset::kDepthDir, td));
    depth += format_tum_file_line(td, dataset::frame_image_path(dataset::kDepthDir, td));
  }
  test::write_text(dir / "rgb.txt", rgb);
  test::write_text(dir / "depth.txt", depth);
  test::write_text(dir / "groundtruth.txt", "# ground truth\n0.000000 1 2 3 0 0 0 1\n");
}

// A small dataset in our format: 5 frames of 32x24 at 10 Hz, odometry at 20 Hz, two Wi-Fi scans.
void write_ours(const fs::path& dir) {
  const int w = 32, h = 24, frames = 5;
  std::string rgb, depth, assoc, gt, images;
  for (int k = 0; k < frames; ++k) {
    const Timestamp t = frame_time(k);
    write_frame_images(dir, t, k, w, h);
    const FramePair p{t, dataset::frame_image_path(dataset::kRgbDir, t), t,
                      dataset::frame_image_path(dataset::kDepthDir, t), 0};
    rgb += format_tum_file_line(t, p.rgb_path);
    depth += format_tum_file_line(t, p.depth_path);
    assoc += format_association_line(p);
    gt += format_tum_line(StampedPose::from_pose(t, camera_pose_from_planar(0.1 * k, 0, 0, 0.5)));
    gt += "\n";
    images += format_checksum_line(sha256_file_hex(dir / p.rgb_path), p.rgb_path);
    images += format_checksum_line(sha256_file_hex(dir / p.depth_path), p.depth_path);
  }
  std::string odo;
  for (int j = 0; j < 2 * frames - 1; ++j) {
    Pose pose = Pose::Identity();
    pose.translation().x() = 0.05 * j;
    odo +=
        format_tum_line(StampedPose::from_pose(Timestamp::from_ns(j * 50'000'000LL), pose)) + "\n";
  }
  WifiScan a, b;
  a.start_time = Timestamp{0};
  a.time = a.end_time = frame_time(1);  // same time as frame 1: the scan comes first
  a.readings = {{*MacAddress::parse("02:00:00:00:01:00"), 2412000, -50, "campus"},
                {*MacAddress::parse("02:00:00:00:01:08"), 5180000, -61, "campus"}};
  b.start_time = frame_time(2);
  b.time = b.end_time = Timestamp::from_ns(frame_time(3).ns + 1000);
  b.readings = {{*MacAddress::parse("02:00:00:00:02:00"), 2437000, -70, "lab"}};
  test::write_text(dir / "rgb.txt", rgb);
  test::write_text(dir / "depth.txt", depth);
  test::write_text(dir / "associations.txt", assoc);
  test::write_text(dir / "groundtruth.txt", gt);
  test::write_text(dir / "odometry.txt", odo);
  test::write_text(dir / "wifi.csv",
                   wifi_csv_header() + "\n" + format_wifi_csv_rows(a) + format_wifi_csv_rows(b));
  test::write_text(dir / "images.sha256", images);
  DatasetCalibration cal;
  cal.intrinsics = {w, h, 30.0, 30.0, 15.5, 11.5};
  cal.camera_fps = 10.0;
  cal.camera_in_base = camera_pose_from_planar(0, 0, 0, 0.5);
  cal.odometry_rate_hz = 20.0;
  cal.sensor_model = {{"depth_sensor", {{"noise", "false"}, {"baseline_m", "0.075"}}}};
  test::write_text(dir / "calibration.yaml", calibration_to_yaml(cal));
  DatasetManifest m;
  m.versions = {{"wifislam", "test"}};
  m.parameters_json = R"({"seed": 1})";
  m.counts = {{"frames", frames},
              {"odometry_readings", 2 * frames - 1},
              {"wifi_scans", 2},
              {"groundtruth_poses", frames}};
  for (const char* f : {"rgb.txt", "depth.txt", "associations.txt", "groundtruth.txt",
                        "odometry.txt", "wifi.csv", "images.sha256", "calibration.yaml"}) {
    m.files.push_back(describe_dataset_file(dir, f));
  }
  test::write_text(dir / "manifest.json", manifest_to_json(m));
}

std::vector<SensorEvent> read_all(DatasetReader& reader) {
  std::vector<SensorEvent> events;
  while (auto e = reader.next()) events.push_back(std::move(*e));
  return events;
}

TEST(DatasetReader, PlainTumFolderWithoutWifiSaysSo) {
  const auto dir = test::fresh_folder("tum");
  write_plain_tum(dir, 3);
  DatasetReader reader(dir);
  EXPECT_FALSE(reader.has_wifi());
  EXPECT_FALSE(reader.has_odometry());
  EXPECT_FALSE(reader.has_manifest());
  EXPECT_NE(reader.description().find("no Wi-Fi"), std::string::npos) << reader.description();
  EXPECT_NE(reader.description().find("default Kinect v1"), std::string::npos);
  EXPECT_EQ(reader.intrinsics(), CameraIntrinsics::kinect_v1());
  const auto events = read_all(reader);
  ASSERT_EQ(events.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const auto& frame = std::get<RgbdFrame>(events[k]);
    EXPECT_EQ(frame.index, k);
    EXPECT_EQ(frame.time, frame_time(k));
    EXPECT_EQ(frame.rgb.type(), CV_8UC3);
    EXPECT_EQ(frame.rgb.at<cv::Vec3b>(10, 10), cv::Vec3b(k, 2 * k, 3 * k));
    EXPECT_EQ(frame.depth_m.type(), CV_32FC1);
    EXPECT_FLOAT_EQ(frame.depth_m.at<float>(5, 5), static_cast<float>(k + 1));
    EXPECT_EQ(frame.depth_path,
              "depth/" + Timestamp::from_ns(frame.time.ns + 3'000'000).to_string() + ".png");
  }
  EXPECT_EQ(read_ground_truth(dir).size(), 1u);
}

TEST(DatasetReader, StreamsOurDatasetInTimeOrderWithTiesOdometryWifiFrame) {
  const auto dir = test::fresh_folder("ours");
  write_ours(dir);
  DatasetReader reader(dir);
  EXPECT_TRUE(reader.has_wifi());
  EXPECT_TRUE(reader.has_odometry());
  EXPECT_EQ(reader.frame_count(), 5);
  EXPECT_EQ(reader.wifi_scan_count(), 2);
  EXPECT_EQ(reader.odometry_count(), 9);
  EXPECT_EQ(reader.intrinsics().width_px, 32);
  EXPECT_TRUE(reader.camera_in_base().isApprox(camera_pose_from_planar(0, 0, 0, 0.5), 1e-15));
  ASSERT_EQ(reader.calibration().sensor_model.size(), 1u);
  EXPECT_EQ(reader.calibration().sensor_model[0].values[1].second, "0.075");
  const auto events = read_all(reader);
  ASSERT_EQ(events.size(), 5u + 2u + 9u);
  for (std::size_t i = 1; i < events.size(); ++i) {
    EXPECT_LE(event_time(events[i - 1]), event_time(events[i]));
    if (event_time(events[i - 1]) == event_time(events[i])) {
      // Variant indices: frame 0, scan 1, odometry 2; ties come odometry first.
      EXPECT_GE(events[i - 1].index(), events[i].index()) << "tie order";
    }
  }
  // At t = 0.1 s: odometry (t = 0.1), then the scan, then frame 1.
  std::vector<std::size_t> kinds_at_100ms;
  for (const auto& e : events)
    if (event_time(e) == frame_time(1)) kinds_at_100ms.push_back(e.index());
  EXPECT_EQ(kinds_at_100ms, (std::vector<std::size_t>{2, 1, 0}));
  int scans = 0;
  for (const auto& e : events) {
    if (const auto* s = std::get_if<WifiScan>(&e)) {
      ++scans;
      EXPECT_EQ(s->readings.size(), scans == 1 ? 2u : 1u);
    }
  }
  EXPECT_EQ(scans, 2);
  reader.rewind();
  EXPECT_EQ(read_all(reader).size(), events.size());
}

std::string open_error(const fs::path& dir, DatasetReaderOptions options = {}) {
  try {
    DatasetReader reader(dir, options);
    while (reader.next()) {
    }
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(DatasetReader, MissingPngIsAnErrorNamingTheListLine) {
  const auto dir = test::fresh_folder("missing");
  write_ours(dir);
  fs::remove(dir / dataset::frame_image_path(dataset::kDepthDir, frame_time(3)));
  const std::string e = open_error(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("associations.txt:4"), std::string::npos) << e;
  EXPECT_NE(e.find("depth/0.300000.png"), std::string::npos) << e;
}

TEST(DatasetReader, ManifestMismatchIsAnErrorUnlessVerificationIsOff) {
  const auto dir = test::fresh_folder("mismatch");
  write_ours(dir);
  test::write_text(dir / "odometry.txt", test::read_file(dir / "odometry.txt") + "\n");
  std::string e = open_error(dir);
  EXPECT_NE(e.find("odometry.txt"), std::string::npos) << e;
  EXPECT_NE(e.find("manifest mismatch"), std::string::npos) << e;
  EXPECT_NE(e.find("--no-verify"), std::string::npos) << e;
  EXPECT_EQ(open_error(dir, {.verify_checksums = false}), "no error");
}

TEST(DatasetReader, ChangedImageIsCaughtWhenItIsRead) {
  const auto dir = test::fresh_folder("image");
  write_ours(dir);
  write_png(dir / dataset::frame_image_path(dataset::kRgbDir, frame_time(2)),
            cv::Mat(24, 32, CV_8UC3, cv::Scalar(9, 9, 9)));
  const std::string e = open_error(dir);
  EXPECT_NE(e.find("rgb/0.200000.png"), std::string::npos) << e;
  EXPECT_NE(e.find("manifest mismatch"), std::string::npos) << e;
  EXPECT_EQ(open_error(dir, {.verify_checksums = false}), "no error");
}

// Decoding ahead on other threads changes the wall time only: the same events with the same
// pixels, and an error still surfaces at the frame it belongs to, after every earlier frame.
TEST(DatasetReader, PrefetchingGivesTheSameFramesAndTheSameErrorAtTheSameFrame) {
  const auto dir = test::fresh_folder("prefetch");
  write_ours(dir);
  for (int prefetch : {1, 4, 16}) {
    DatasetReader inline_reader(dir, {.prefetch_frames = 0});
    DatasetReader ahead(dir, {.prefetch_frames = prefetch});
    const auto a = read_all(inline_reader);
    const auto b = read_all(ahead);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].index(), b[i].index()) << i;
      if (const auto* fa = std::get_if<RgbdFrame>(&a[i])) {
        const auto& fb = std::get<RgbdFrame>(b[i]);
        EXPECT_EQ(fa->index, fb.index);
        EXPECT_EQ(cv::norm(fa->rgb, fb.rgb, cv::NORM_INF), 0.0);
        EXPECT_EQ(cv::norm(fa->depth_m, fb.depth_m, cv::NORM_INF), 0.0);
      }
    }
  }
  // Frame 3's depth image changed: frames 0..2 come out, then the error naming the file.
  write_png(dir / dataset::frame_image_path(dataset::kDepthDir, frame_time(3)),
            cv::Mat(24, 32, CV_16UC1, cv::Scalar(1234)));
  DatasetReader reader(dir, {.prefetch_frames = 4});
  int frames = 0;
  try {
    while (auto e = reader.next()) frames += std::holds_alternative<RgbdFrame>(*e) ? 1 : 0;
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("depth/0.300000.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(frames, 3);
}

TEST(DatasetReader, CorruptFilesAreErrorsWithFileAndLine) {
  const auto dir = test::fresh_folder("corrupt");
  write_ours(dir);
  // A malformed wifi.csv row.
  const std::string wifi = test::read_file(dir / "wifi.csv");
  test::write_text(dir / "wifi.csv", wifi + "400001,wifi0,not-a-mac,2412000,-50,x,0,400001\n");
  std::string e = open_error(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("wifi.csv:5"), std::string::npos) << e;
  EXPECT_NE(e.find("not-a-mac"), std::string::npos) << e;
  test::write_text(dir / "wifi.csv", wifi);
  // A truncated odometry line.
  const std::string odo = test::read_file(dir / "odometry.txt");
  test::write_text(dir / "odometry.txt", odo.substr(0, odo.size() - 10));
  e = open_error(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("odometry.txt:9"), std::string::npos) << e;
  test::write_text(dir / "odometry.txt", odo);
  // Found by fuzzing: calibration.yaml with a scalar where a mapping belongs escaped as a
  // yaml-cpp exception (an internal error); so did a sensor_model group that is not a mapping.
  const std::string calibration = test::read_file(dir / "calibration.yaml");
  for (const std::string& bad :
       {std::string("camera: 5\n"),
        calibration.substr(0, calibration.find("sensor_model:")) + "sensor_model: [1, 2]\n",
        calibration.substr(0, calibration.find("depth:")) + "depth: 3\n"}) {
    test::write_text(dir / "calibration.yaml", bad);
    e = open_error(dir, {.verify_checksums = false});
    EXPECT_NE(e.find("calibration.yaml"), std::string::npos) << e;
    EXPECT_NE(e.find("expected a mapping"), std::string::npos) << e;
  }
  test::write_text(dir / "calibration.yaml",
                   std::regex_replace(calibration, std::regex("width_px: 32"), "width_px: 1e300"));
  e = open_error(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("camera.width_px"), std::string::npos) << e;
  test::write_text(dir / "calibration.yaml", calibration);
  // A PNG that is not an image.
  test::write_text(dir / dataset::frame_image_path(dataset::kDepthDir, frame_time(4)), "garbage");
  e = open_error(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("depth/0.400000.png"), std::string::npos) << e;
  EXPECT_NE(e.find("not a readable PNG"), std::string::npos) << e;
}

// Issue 18: a 16-bit image in the RGB list (a depth map, say) was scaled to 8 bits and read as
// colour, in a plain TUM folder and with --no-verify alike.
TEST(DatasetReader, SixteenBitImageInTheRgbSlotIsRefused) {
  const auto dir = test::fresh_folder("rgb16");
  write_plain_tum(dir, 3);
  const fs::path rgb = dir / dataset::frame_image_path(dataset::kRgbDir, frame_time(1));
  write_png(rgb, cv::Mat(480, 640, CV_16UC1, cv::Scalar(5000)));
  std::string e = open_error(dir);
  EXPECT_NE(e.find("rgb/0.100000.png"), std::string::npos) << e;
  EXPECT_NE(e.find("8 bits per channel"), std::string::npos) << e;
  EXPECT_NE(e.find("has 16"), std::string::npos) << e;
  EXPECT_NE(e.find("rgb.txt:5"), std::string::npos) << e;
  write_png(rgb, cv::Mat(480, 640, CV_16UC3, cv::Scalar(5000, 5000, 5000)));
  EXPECT_NE(open_error(dir).find("8 bits per channel"), std::string::npos);
}

// Issue 34: grey and colour-with-alpha images in the RGB list were expanded or stripped to
// colour without a word. The RGB list holds 8-bit, 3-channel images (TUM's format); anything else
// is refused naming the image and the list line.
TEST(DatasetReader, GreyAndAlphaImagesInTheRgbListAreRefused) {
  const auto dir = test::fresh_folder("rgb_channels");
  write_plain_tum(dir, 3);
  const fs::path rgb = dir / dataset::frame_image_path(dataset::kRgbDir, frame_time(1));
  for (const auto& [image, what] :
       {std::pair{cv::Mat(480, 640, CV_8UC1, cv::Scalar(7)), "has 1 (grey"},
        std::pair{cv::Mat(480, 640, CV_8UC4, cv::Scalar(1, 2, 3, 255)), "has 4 (colour with"}}) {
    write_png(rgb, image);
    for (const bool verify : {true, false}) {
      const std::string e = open_error(dir, {.verify_checksums = verify});
      EXPECT_NE(e.find("rgb/0.100000.png"), std::string::npos) << e;
      EXPECT_NE(e.find("3 colour channels"), std::string::npos) << e;
      EXPECT_NE(e.find(what), std::string::npos) << e;
      EXPECT_NE(e.find("rgb.txt:5"), std::string::npos) << e;
    }
  }
  write_png(rgb, cv::Mat(480, 640, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_EQ(open_error(dir), "no error");
}

// The kind of error an opening or a read gives, with its message.
template <typename E>
std::string error_of_kind(const fs::path& dir, DatasetReaderOptions options = {}) {
  try {
    DatasetReader reader(dir, options);
    while (reader.next()) {
    }
  } catch (const E& e) {
    return e.what();
  } catch (const Error& e) {
    return std::string("another kind of error: ") + e.what();
  }
  return "no error";
}

// Issue 34: zero frames read as a dataset (check passed it, slam wrote an empty run). An empty
// associations.txt, empty lists, or lists whose stamps never pair are bad input, verified or not.
TEST(DatasetReader, ADatasetWithoutFramesIsRefused) {
  const auto dir = test::fresh_folder("zero");
  write_ours(dir);
  test::write_text(dir / "associations.txt", "# t_rgb rgb t_depth depth\n");
  std::string e = error_of_kind<InvalidInputError>(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("associations.txt: lists no frames"), std::string::npos) << e;
  const auto plain = test::fresh_folder("zero_plain");
  write_plain_tum(plain, 2);
  test::write_text(plain / "rgb.txt", "# nothing\n");
  e = error_of_kind<InvalidInputError>(plain);
  EXPECT_NE(e.find("rgb.txt lists no images"), std::string::npos) << e;
  test::write_text(plain / "rgb.txt",
                   "5.000000 " + dataset::frame_image_path(dataset::kRgbDir, frame_time(0)) + "\n");
  e = error_of_kind<InvalidInputError>(plain);
  EXPECT_NE(e.find("no stamp in rgb.txt is within 0.02 s"), std::string::npos) << e;
}

// Issue 34: what an interrupted `generate` leaves (marker, no manifest) was read by `check`
// while `slam` refused it. The reader refuses it for every command, unless checksums are off.
TEST(DatasetReader, AnUnfinishedDatasetIsRefusedUnlessVerificationIsOff) {
  const auto dir = test::fresh_folder("run.partial");
  write_ours(dir);
  fs::remove(dir / "manifest.json");
  EXPECT_TRUE(is_unfinished_dataset(dir));
  std::string e = error_of_kind<InvalidInputError>(dir);
  EXPECT_NE(e.find("an unfinished dataset"), std::string::npos) << e;
  EXPECT_EQ(open_error(dir, {.verify_checksums = false}), "no error");
  // The marker alone says so too, whatever the name; a plain TUM folder has neither.
  const auto marked = test::fresh_folder("marked");
  write_plain_tum(marked, 2);
  EXPECT_FALSE(is_unfinished_dataset(marked));
  test::write_text(marked / ".wifislam-output", "");
  EXPECT_TRUE(is_unfinished_dataset(marked));
  EXPECT_NE(error_of_kind<InvalidInputError>(marked).find("unfinished"), std::string::npos);
}

// Issue 34: two frames stamped alike passed (and a list stamped twice alike); a stamp must be
// later than the previous line's in every list.
TEST(DatasetReader, EqualStampsInTheListsAreRefusedAtTheLine) {
  const auto dir = test::fresh_folder("equal");
  write_ours(dir);
  std::string assoc = test::read_file(dir / "associations.txt");
  const std::size_t second = assoc.find('\n') + 1;
  const std::string first_line = assoc.substr(0, second);
  test::write_text(dir / "associations.txt", first_line + assoc);
  std::string e = error_of_kind<ParseError>(dir, {.verify_checksums = false});
  EXPECT_NE(e.find("associations.txt:2"), std::string::npos) << e;
  EXPECT_NE(e.find("not later than the previous line"), std::string::npos) << e;
  const auto plain = test::fresh_folder("equal_plain");
  write_plain_tum(plain, 3);
  std::string depth = test::read_file(plain / "depth.txt");
  const std::size_t last = depth.rfind('\n', depth.size() - 2) + 1;
  test::write_text(plain / "depth.txt", depth + depth.substr(last));
  e = error_of_kind<ParseError>(plain);
  EXPECT_NE(e.find("depth.txt:7"), std::string::npos) << e;
}

// Issue 34: with associations.txt there, rgb.txt and depth.txt were never read: empty, shuffled
// or escaping lists passed. They are checked as when they are the only lists, and must list
// every image the associations pair.
TEST(DatasetReader, TheListsBesideAssociationsAreCheckedToo) {
  const auto dir = test::fresh_folder("lists");
  write_ours(dir);
  const std::string rgb = test::read_file(dir / "rgb.txt");
  const DatasetReaderOptions unverified{.verify_checksums = false};
  test::write_text(dir / "rgb.txt", "");
  std::string e = error_of_kind<ParseError>(dir, unverified);
  EXPECT_NE(e.find("associations.txt:1"), std::string::npos) << e;
  EXPECT_NE(e.find("is not listed in rgb.txt"), std::string::npos) << e;
  // Shuffled: the second line first.
  const std::size_t cut = rgb.find('\n') + 1, cut2 = rgb.find('\n', cut) + 1;
  test::write_text(dir / "rgb.txt",
                   rgb.substr(cut, cut2 - cut) + rgb.substr(0, cut) + rgb.substr(cut2));
  e = error_of_kind<ParseError>(dir, unverified);
  EXPECT_NE(e.find("rgb.txt:2"), std::string::npos) << e;
  test::write_text(dir / "rgb.txt", rgb + "9.000000 ../../etc/passwd\n");
  e = error_of_kind<ParseError>(dir, unverified);
  EXPECT_NE(e.find("rgb.txt:6"), std::string::npos) << e;
  EXPECT_NE(e.find("leaves the dataset folder"), std::string::npos) << e;
  test::write_text(dir / "rgb.txt", rgb);
  EXPECT_EQ(open_error(dir), "no error");
}

// Issue 34: an image path may not be absolute or climb out of the dataset folder.
TEST(DatasetReader, ImagePathsOutsideTheFolderAreRefused) {
  const auto dir = test::fresh_folder("escape");
  write_ours(dir);
  const std::string assoc = test::read_file(dir / "associations.txt");
  const std::string image = dataset::frame_image_path(dataset::kRgbDir, frame_time(0));
  for (const std::string& path :
       std::vector<std::string>{(dir / image).string(),
                                "../" + dir.filename().string() + "/" + image, "rgb/../../x.png"}) {
    std::string edited = assoc;
    edited.replace(edited.find(image), image.size(), path);
    test::write_text(dir / "associations.txt", edited);
    const std::string e = error_of_kind<ParseError>(dir, {.verify_checksums = false});
    EXPECT_NE(e.find("associations.txt:1"), std::string::npos) << path << ": " << e;
    EXPECT_NE(e.find("leaves the dataset folder"), std::string::npos) << path << ": " << e;
  }
}

// Issue 34: an image that is a symlink to /dev/zero or a folder said "does not exist" (an I/O
// error, exit 3). It exists and is not a PNG: bad input. A missing image stays an I/O error.
TEST(DatasetReader, AnImageThatIsAFolderOrADeviceIsBadInputNotMissing) {
  const auto dir = test::fresh_folder("not_png");
  write_ours(dir);
  const fs::path rgb = dir / dataset::frame_image_path(dataset::kRgbDir, frame_time(2));
  const DatasetReaderOptions unverified{.verify_checksums = false};
  fs::remove(rgb);
  fs::create_symlink("/dev/zero", rgb);
  std::string e = error_of_kind<ParseError>(dir, unverified);
  EXPECT_NE(e.find("associations.txt:3"), std::string::npos) << e;
  EXPECT_NE(e.find("rgb/0.200000.png is not a regular file"), std::string::npos) << e;
  fs::remove(rgb);
  fs::create_directories(rgb);
  e = error_of_kind<ParseError>(dir, unverified);
  EXPECT_NE(e.find("is a folder, not a PNG image"), std::string::npos) << e;
  fs::remove(rgb);
  e = error_of_kind<IoError>(dir, unverified);
  EXPECT_NE(e.find("does not exist"), std::string::npos) << e;
}

TEST(DatasetReader, TruncatedGroundTruthIsAnError) {
  const auto dir = test::fresh_folder("gt");
  write_ours(dir);
  EXPECT_EQ(read_ground_truth(dir).size(), 5u);
  const std::string gt = test::read_file(dir / "groundtruth.txt");
  // Cut in the middle of the last line.
  test::write_text(dir / "groundtruth.txt", gt.substr(0, gt.size() - 12));
  try {
    read_ground_truth(dir);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("groundtruth.txt:5"), std::string::npos) << e.what();
  }
  // Cut at a line boundary: well-formed but short; the manifest's count catches it.
  test::write_text(dir / "groundtruth.txt", gt.substr(0, gt.rfind('\n', gt.size() - 2) + 1));
  try {
    read_ground_truth(dir);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("groundtruth.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("manifest mismatch"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_ground_truth(dir, false).size(), 4u);
}

TEST(DatasetReader, FolderWithoutFramesIsNotADataset) {
  const auto dir = test::fresh_folder("empty");
  const std::string e = open_error(dir);
  EXPECT_NE(e.find("not a dataset folder: it holds none of"), std::string::npos) << e;
  // A run folder is named as one, not as an unfinished dataset (it carries the output marker).
  const auto run = test::fresh_folder("run_folder");
  test::write_text(run / ".wifislam-output", "");
  test::write_text(run / "run.json", "{}");
  test::write_text(run / "trajectory.txt", "");
  const std::string e_run = open_error(run);
  EXPECT_NE(e_run.find("a SLAM run folder"), std::string::npos) << e_run;
  EXPECT_FALSE(is_unfinished_dataset(run));
  EXPECT_NE(open_error(dir / "nope").find("does not exist"), std::string::npos);
  // Issue 34: a file given for a dataset folder is bad input, as a folder for a scene file is.
  test::write_text(dir / "file.txt", "x");
  const std::string e_file = error_of_kind<InvalidInputError>(dir / "file.txt");
  EXPECT_NE(e_file.find("not a dataset folder (it is a file)"), std::string::npos) << e_file;
}

}  // namespace
}  // namespace wifislam
