// `wifislam export DATASET --for rtabmap|orbslam2 -o DIR` as its peers' dataset tools read the
// result: every frame name is a positive Unix-like stamp (RTAB-Map's rtabmap-rgbd_dataset rejects
// "0.000000.png"), rgb_sync and depth_sync hold the same names, ORB-SLAM2's associations.txt names
// exactly the linked files, every link resolves to the dataset's own image (same bytes, nothing
// copied), the settings file reads back through OpenCV's FileStorage (as ORB-SLAM2 reads it) with
// the calibration's intrinsics, and so does rtabmap_calib.yaml (as RTAB-Map's CameraModel::load
// reads it); refusals are exit 2 before anything is written, and a folder whose name would make
// rtabmap-rgbd_dataset use another TUM Kinect's intrinsics warns.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core/persistence.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/dataset_calibration.hpp"
#include "core/shell_quoted.hpp"
#include "core/timestamp.hpp"
#include "core/tum_file_list.hpp"
#include "tests/cli/shared_dataset.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;
using test::read_file;

/// TUM's freiburg1 Kinect, as a scene's sensors.camera.
constexpr const char* kFreiburg1Camera =
    "radio: {environment: office}\n"
    "sensors: {camera: {fx_px: 517.3, fy_px: 516.5, cx_px: 318.6, cy_px: 255.3}}";

class ExportCli : public ::testing::Test {
 protected:
  // Three tiny datasets shared by the tests (each export writes a folder of its own): one with
  // the default calibration (525 px, no TUM camera's), one with freiburg1's intrinsics, one whose
  // time starts at zero.
  static void SetUpTestSuite() {
    const std::string office = "radio: {environment: office}";
    for (const auto& [name, yaml] :
         {std::pair<std::string, std::string>{"default_ds", test::kTinyLoopYaml},
          {"fr1_ds", test::tiny_loop_yaml_with(office, kFreiburg1Camera)},
          {"origin0_ds",
           test::tiny_loop_yaml_with(office, office + "\nsensors: {time_origin_s: 0}")}}) {
      datasets_[name] = test::shared_dataset(yaml, "--fps 2 --max-frames 6");
      generated_ = generated_ && !datasets_[name].empty();
    }
  }
  void SetUp() override {
    ASSERT_TRUE(generated_) << "wifislam generate failed";
    scratch_ = test::scratch_folder();
  }
  void TearDown() override { fs::remove_all(scratch_); }

  test::CliResult wifislam(const std::string& args) { return test::run_wifislam(args, scratch_); }
  test::CliResult export_to(const std::string& dataset_name, const std::string& peer,
                            const fs::path& out, const std::string& more = "") {
    return wifislam("export " + dataset(dataset_name).string() + " --for " + peer + " -o " +
                    out.string() + " " + more);
  }

  /// The dataset's frame pairs as its associations.txt lists them.
  static std::vector<FramePair> dataset_pairs(const std::string& dataset_name) {
    std::vector<FramePair> pairs;
    AssociationsReader reader((dataset(dataset_name) / "associations.txt").string());
    while (auto p = reader.next()) pairs.push_back(*p);
    return pairs;
  }

  /// Sorted file names in `dir`.
  static std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  /// `link` is a relative symbolic link whose target is `image`, byte for byte the same file.
  static void expect_links_to(const fs::path& link, const fs::path& image) {
    ASSERT_TRUE(fs::is_symlink(link)) << link;
    EXPECT_TRUE(fs::read_symlink(link).is_relative()) << link << " -> " << fs::read_symlink(link);
    ASSERT_TRUE(fs::exists(link)) << link << " dangles";
    EXPECT_EQ(fs::canonical(link), fs::canonical(image)) << link;
    const std::string bytes = test::read_file(link);
    EXPECT_FALSE(bytes.empty()) << link;
    EXPECT_EQ(bytes, test::read_file(image)) << link;
  }

  /// The stamp a frame file is named by, as rtabmap-rgbd_dataset reads it (a decimal number of
  /// seconds before ".png"), and as we do (exactly).
  static void expect_unix_stamp_name(const std::string& name, Timestamp expected) {
    ASSERT_TRUE(name.ends_with(".png")) << name;
    const std::string stem = name.substr(0, name.size() - 4);
    const auto t = Timestamp::parse(stem);
    ASSERT_TRUE(t.has_value()) << name;
    EXPECT_EQ(*t, expected) << name;
    EXPECT_GT(std::strtod(stem.c_str(), nullptr), 1e9) << name << " is no Unix time";
  }

  static fs::path dataset(const std::string& name) { return datasets_.at(name); }

  static inline std::map<std::string, fs::path> datasets_;
  static inline bool generated_ = true;
  fs::path scratch_;
};

TEST_F(ExportCli, RtabmapLayoutNamesEveryPairByItsPositiveUnixStampAndLinksTheDatasetsImages) {
  const fs::path out = scratch_ / "tiny_freiburg1";
  const auto r = export_to("fr1_ds", "rtabmap", out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("freiburg1"), std::string::npos) << r.out;

  const std::vector<FramePair> pairs = dataset_pairs("fr1_ds");
  ASSERT_EQ(pairs.size(), 6u);
  const std::vector<std::string> rgb = names_in(out / "rgb_sync");
  EXPECT_EQ(rgb, names_in(out / "depth_sync"));
  ASSERT_EQ(rgb.size(), pairs.size());
  // Sorted names are the frames in time order (the tool pairs the folders by position).
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    expect_unix_stamp_name(rgb[i], pairs[i].rgb_time);
    expect_links_to(out / "rgb_sync" / rgb[i], dataset("fr1_ds") / pairs[i].rgb_path);
    expect_links_to(out / "depth_sync" / rgb[i], dataset("fr1_ds") / pairs[i].depth_path);
  }
  expect_links_to(out / "groundtruth.txt", dataset("fr1_ds") / "groundtruth.txt");

  const auto j = nlohmann::json::parse(test::read_file(out / "export.json"));
  EXPECT_EQ(j.at("peer"), "rtabmap");
  EXPECT_EQ(j.at("tum_camera"), "freiburg1");
  EXPECT_EQ(j.at("frames"), 6);
  EXPECT_TRUE(j.at("warnings").empty());
}

TEST_F(ExportCli, Orbslam2LayoutListsExactlyTheLinkedImagesAndCarriesTheCalibration) {
  const fs::path out = scratch_ / "orb";
  const auto r = export_to("default_ds", "orbslam2", out);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const std::vector<FramePair> pairs = dataset_pairs("default_ds");
  std::ifstream in(out / "associations.txt");
  std::set<std::string> listed_rgb, listed_depth;
  std::size_t k = 0;
  for (std::string line; std::getline(in, line); ++k) {
    // rgbd_tum reads every line as a frame: no comments, four fields.
    std::istringstream fields(line);
    std::string t_rgb, rgb, t_depth, depth, extra;
    ASSERT_TRUE(fields >> t_rgb >> rgb >> t_depth >> depth) << line;
    EXPECT_FALSE(fields >> extra) << line;
    ASSERT_LT(k, pairs.size());
    EXPECT_EQ(rgb, "rgb/" + t_rgb + ".png");
    EXPECT_EQ(depth, "depth/" + t_depth + ".png");
    expect_unix_stamp_name(fs::path(rgb).filename().string(), pairs[k].rgb_time);
    expect_unix_stamp_name(fs::path(depth).filename().string(), pairs[k].depth_time);
    expect_links_to(out / rgb, dataset("default_ds") / pairs[k].rgb_path);
    expect_links_to(out / depth, dataset("default_ds") / pairs[k].depth_path);
    listed_rgb.insert(fs::path(rgb).filename().string());
    listed_depth.insert(fs::path(depth).filename().string());
  }
  EXPECT_EQ(k, pairs.size());
  const auto rgb_names = names_in(out / "rgb"), depth_names = names_in(out / "depth");
  EXPECT_EQ(std::set<std::string>(rgb_names.begin(), rgb_names.end()), listed_rgb);
  EXPECT_EQ(std::set<std::string>(depth_names.begin(), depth_names.end()), listed_depth);

  // The settings as ORB-SLAM2 reads them (cv::FileStorage), against the dataset's calibration.
  const DatasetCalibration c = read_calibration_yaml(dataset("default_ds") / "calibration.yaml");
  EXPECT_TRUE(test::read_file(out / "orbslam2_settings.yaml").starts_with("%YAML:1.0\n"));
  cv::FileStorage settings((out / "orbslam2_settings.yaml").string(), cv::FileStorage::READ);
  ASSERT_TRUE(settings.isOpened());
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.fx"]), c.intrinsics.fx_px);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.fy"]), c.intrinsics.fy_px);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.cx"]), c.intrinsics.cx_px);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.cy"]), c.intrinsics.cy_px);
  for (const char* d : {"Camera.k1", "Camera.k2", "Camera.p1", "Camera.p2", "Camera.k3"}) {
    EXPECT_EQ(static_cast<double>(settings[d]), 0.0) << d;
  }
  EXPECT_EQ(static_cast<int>(settings["Camera.width"]), c.intrinsics.width_px);
  EXPECT_EQ(static_cast<int>(settings["Camera.height"]), c.intrinsics.height_px);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.fps"]), c.camera_fps);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.bf"]), 0.075 * c.intrinsics.fx_px);
  EXPECT_EQ(static_cast<int>(settings["Camera.RGB"]), 1);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["ThDepth"]), 40.0);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["DepthMapFactor"]), 5000.0);
  EXPECT_EQ(static_cast<int>(settings["ORBextractor.nFeatures"]), 1000);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["ORBextractor.scaleFactor"]), 1.2);
  EXPECT_EQ(static_cast<int>(settings["ORBextractor.nLevels"]), 8);
  EXPECT_EQ(static_cast<int>(settings["ORBextractor.iniThFAST"]), 20);
  EXPECT_EQ(static_cast<int>(settings["ORBextractor.minThFAST"]), 7);
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Viewer.ViewpointF"]), 500.0);
  expect_links_to(out / "groundtruth.txt", dataset("default_ds") / "groundtruth.txt");
}

/// rtabmap_calib.yaml read as RTAB-Map's CameraModel::load reads it (OpenCV FileStorage), with the
/// shapes its UASSERTs demand: camera_matrix 3x3, distortion_coefficients 1x(4|5|8),
/// rectification_matrix 3x3, projection_matrix 3x4, local_transform 3x4.
void expect_rtabmap_calibration(const fs::path& file, const CameraIntrinsics& k) {
  cv::FileStorage fs(file.string(), cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened()) << file;
  EXPECT_EQ(static_cast<std::string>(fs["camera_name"]), "rtabmap_calib");
  EXPECT_EQ(static_cast<int>(fs["image_width"]), k.width_px);
  EXPECT_EQ(static_cast<int>(fs["image_height"]), k.height_px);
  const auto matrix = [&](const char* key, int rows, int cols) {
    const cv::FileNode n = fs[key];
    EXPECT_FALSE(n.empty()) << key;
    EXPECT_EQ(static_cast<int>(n["rows"]), rows) << key;
    EXPECT_EQ(static_cast<int>(n["cols"]), cols) << key;
    std::vector<double> data;
    n["data"] >> data;
    EXPECT_EQ(data.size(), static_cast<std::size_t>(rows * cols)) << key;
    return data;
  };
  const std::vector<double> kk = matrix("camera_matrix", 3, 3);
  EXPECT_EQ(kk, (std::vector<double>{k.fx_px, 0, k.cx_px, 0, k.fy_px, k.cy_px, 0, 0, 1}));
  EXPECT_EQ(matrix("distortion_coefficients", 1, 5), std::vector<double>(5, 0.0));
  EXPECT_EQ(static_cast<std::string>(fs["distortion_model"]), "plumb_bob");
  EXPECT_EQ(matrix("rectification_matrix", 3, 3), (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(matrix("projection_matrix", 3, 4),
            (std::vector<double>{k.fx_px, 0, k.cx_px, 0, 0, k.fy_px, k.cy_px, 0, 0, 0, 1, 0}));
  // rtabmap-rgbd_dataset's own optical rotation (camera base frame -> optical frame).
  EXPECT_EQ(matrix("local_transform", 3, 4),
            (std::vector<double>{0, 0, 1, 0, -1, 0, 0, 0, 0, -1, 0, 0}));
}

// A folder without calibration.yaml (a plain TUM one): ORB-SLAM2's Camera.fps was the reader's
// assumed 30 whatever rate the frames were taken at. It is now their mean rate.
TEST_F(ExportCli, WithoutACalibrationFileTheFrameRateIsTheFramesOwn) {
  const fs::path plain = scratch_ / "plain";
  fs::copy(dataset("default_ds"), plain, fs::copy_options::recursive);
  fs::remove(plain / "calibration.yaml");
  const fs::path out = scratch_ / "orb_plain";
  const auto r =
      wifislam("export " + plain.string() + " --for orbslam2 --no-verify -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  cv::FileStorage settings((out / "orbslam2_settings.yaml").string(), cv::FileStorage::READ);
  ASSERT_TRUE(settings.isOpened());
  EXPECT_DOUBLE_EQ(static_cast<double>(settings["Camera.fps"]), 2.0);  // generated at --fps 2
}

// The command an export prints (and export.json's "run") is pasted into a shell: a folder with a
// space or a quote in its name split into several arguments. Run through sh with printf in place
// of the program, each path arrives as one argument, unchanged.
TEST_F(ExportCli, ThePrintedCommandPassesEachPathAsOneArgument) {
  const fs::path parent = scratch_ / "it's a folder";
  fs::create_directories(parent);
  const fs::path out = parent / "orb $HOME";
  const auto r = export_to("default_ds", "orbslam2", shell_quoted(out.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string run = nlohmann::json::parse(test::read_file(out / "export.json"))["run"];
  EXPECT_NE(r.out.find("run          " + run + "\n"), std::string::npos) << r.out;
  const std::string program = "Examples/RGB-D/rgbd_tum ";
  ASSERT_EQ(run.rfind(program, 0), 0u) << run;
  run.replace(0, program.size(), "printf '%s\\n' ");
  test::write_file(scratch_ / "run.sh", run + "\n");
  ASSERT_EQ(std::system(("sh " + shell_quoted((scratch_ / "run.sh").string()) + " >" +
                         shell_quoted((scratch_ / "args.txt").string()))
                            .c_str()),
            0);
  EXPECT_EQ(test::read_file(scratch_ / "args.txt"),
            "Vocabulary/ORBvoc.txt\n" + (out / "orbslam2_settings.yaml").string() + "\n" +
                out.string() + "\n" + (out / "associations.txt").string() + "\n");
}

TEST_F(ExportCli, RtabmapCalibrationCarriesTheDatasetsOwnIntrinsicsWhateverTheFolderIsCalled) {
  // Our default camera (525 px) is no TUM Kinect's: the calibration file carries it anyway.
  const fs::path out = scratch_ / "rgbd_export";
  const auto r = export_to("default_ds", "rtabmap", out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("none matches"), std::string::npos) << r.out;
  expect_rtabmap_calibration(out / "rtabmap_calib.yaml", CameraIntrinsics{});
  const auto j = nlohmann::json::parse(test::read_file(out / "export.json"));
  EXPECT_TRUE(j.at("tum_camera").is_null());
  EXPECT_TRUE(j.at("warnings").empty()) << j.dump();

  const fs::path fr1 = scratch_ / "fr1_anything";
  ASSERT_EQ(export_to("fr1_ds", "rtabmap", fr1).exit_code, 0);
  CameraIntrinsics freiburg1;
  freiburg1.fx_px = 517.3;
  freiburg1.fy_px = 516.5;
  freiburg1.cx_px = 318.6;
  freiburg1.cy_px = 255.3;
  expect_rtabmap_calibration(fr1 / "rtabmap_calib.yaml", freiburg1);
}

TEST_F(ExportCli, AFolderNamedForAnotherTumCameraWarnsThatRtabmapWouldUseThatCamera) {
  // The tool replaces rtabmap_calib.yaml with the named Kinect's calibration.
  const auto w = export_to("fr1_ds", "rtabmap", scratch_ / "tiny_freiburg3");
  ASSERT_EQ(w.exit_code, 0) << w.err;
  EXPECT_NE(w.err.find("says freiburg3, so rtabmap-rgbd_dataset would replace rtabmap_calib.yaml "
                       "with freiburg3's intrinsics"),
            std::string::npos)
      << w.err;
  const auto d = export_to("default_ds", "rtabmap", scratch_ / "default_freiburg1");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.err.find("not the dataset's (fx 525 fy 525 cx 319.5 cy 239.5"), std::string::npos)
      << d.err;
  // A name holding the dataset's own camera is no conflict.
  const auto same = export_to("fr1_ds", "rtabmap", scratch_ / "tiny_freiburg1_again");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(same.err.find("warning"), std::string::npos) << same.err;
}

TEST_F(ExportCli, AnExistingExportIsReplacedOnlyWithForce) {
  const fs::path out = scratch_ / "twice";
  ASSERT_EQ(export_to("default_ds", "orbslam2", out).exit_code, 0);
  const auto before = test::listing(out);
  const auto again = export_to("default_ds", "rtabmap", out);
  test::expect_located_bad_input(again, out.string(), "--force");
  EXPECT_EQ(test::listing(out), before);
  const auto forced = export_to("default_ds", "rtabmap", out, "--force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_TRUE(fs::exists(out / "rgb_sync"));
  EXPECT_FALSE(fs::exists(out / "rgb"));
}

TEST_F(ExportCli, AnOutputInsideOrAroundTheDatasetIsRefused) {
  const auto before = test::listing(dataset("default_ds"));
  for (const fs::path& out : {dataset("default_ds") / "export", dataset("default_ds"),
                              dataset("default_ds").parent_path()}) {
    const auto r = export_to("default_ds", "rtabmap", out, "--force");
    test::expect_located_bad_input(r, "output folder " + out.string(), "input of this command");
  }
  EXPECT_EQ(test::listing(dataset("default_ds")), before);
  EXPECT_FALSE(fs::exists(dataset("default_ds") / "export.partial"));
}

TEST_F(ExportCli, ADatasetStartingAtZeroIsRefusedForRtabmapAndNothingIsWritten) {
  const fs::path out = scratch_ / "zero";
  const auto r = export_to("origin0_ds", "rtabmap", out);
  test::expect_located_bad_input(r, "associations.txt:1", "0.000000 is not a positive time");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(scratch_ / "zero.partial"));
  // ORB-SLAM2 reads the times from associations.txt and takes 0 as any other.
  EXPECT_EQ(export_to("origin0_ds", "orbslam2", out).exit_code, 0);
}

TEST_F(ExportCli, ADatasetWithoutImagesIsRefused) {
  const fs::path scene = scratch_ / "tiny.yaml";
  test::write_file(scene, test::kTinyLoopYaml);
  const fs::path ds = scratch_ / "noimg";
  ASSERT_EQ(
      wifislam("generate " + scene.string() + " --no-images --max-frames 4 -q -o " + ds.string())
          .exit_code,
      0);
  const auto r =
      wifislam("export " + ds.string() + " --for orbslam2 -o " + (scratch_ / "out").string());
  test::expect_located_bad_input(r, ds.string(), "no images");
  EXPECT_FALSE(fs::exists(scratch_ / "out"));
}

TEST_F(ExportCli, HelpExplainsBothLayouts) {
  const auto r = wifislam("export --help");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* phrase : {"rgb_sync/<t>.png", "freiburg1", "517.3", "associations.txt",
                             "DepthMapFactor 5000", "0.075 m", "symbolic links", "--force"}) {
    EXPECT_NE(r.out.find(phrase), std::string::npos) << phrase;
  }
}

}  // namespace
}  // namespace wifislam
