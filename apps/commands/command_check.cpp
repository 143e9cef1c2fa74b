// `wifislam check <dataset>`: read a whole dataset (ours or plain TUM RGB-D) the way SLAM would,
// verifying checksums and decoding every image, and print what it holds.
#include <filesystem>
#include <memory>
#include <variant>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/imu_csv.hpp"
#include "core/imu_groundtruth_csv.hpp"

namespace wifislam::cli {

namespace {

struct CheckArgs {
  std::string folder;
  bool no_verify = false;
  bool no_images = false;
};

void run_check(const CheckArgs& args) {
  DatasetReaderOptions options;
  options.verify_checksums = !args.no_verify;
  options.load_images = !args.no_images;
  DatasetReader reader(args.folder, options);
  std::int64_t frames = 0, scans = 0, readings = 0, odometry = 0;
  Timestamp first{0}, last{0};
  bool any = false;
  while (auto event = reader.next()) {
    const Timestamp t = event_time(*event);
    if (!any) first = t;
    last = t;
    any = true;
    if (std::holds_alternative<RgbdFrame>(*event)) ++frames;
    if (const auto* scan = std::get_if<WifiScan>(&*event)) {
      ++scans;
      readings += static_cast<std::int64_t>(scan->readings.size());
    }
    if (std::holds_alternative<OdometryReading>(*event)) ++odometry;
  }
  std::size_t ground_truth = 0;
  try {
    ground_truth = read_ground_truth(args.folder, options.verify_checksums).size();
  } catch (const IoError&) {
    // A dataset without ground truth (some TUM sequences) is still readable.
  }
  // The IMU files are no SLAM input, but `export` hands them to EuRoC, Kapture and ROS readers:
  // read as the exports read them, so a dataset `check` passes is one every export takes.
  const std::filesystem::path folder(args.folder);
  std::string imu;
  if (std::filesystem::is_regular_file(folder / dataset::kImu)) {
    imu = fmt::format(", imu readings {}", read_imu_csv((folder / dataset::kImu).string()).size());
  }
  if (std::filesystem::is_regular_file(folder / dataset::kImuGroundTruth)) {
    imu +=
        fmt::format(", imu ground truth rows {}",
                    read_imu_groundtruth_csv((folder / dataset::kImuGroundTruth).string()).size());
  }
  fmt::print("{}\n", reader.description());
  fmt::print("frames {}, wifi scans {} ({} readings), odometry {}, ground truth poses {}{}\n",
             frames, scans, readings, odometry, ground_truth, imu);
  // Stamps at full precision (Unix times need 16 digits), the span subtracted in nanoseconds.
  fmt::print("time span {} s .. {} s ({:.3f} s)\n", first.to_tum_string(), last.to_tum_string(),
             last.seconds_since(first));
  fmt::print("{}\n", options.verify_checksums && reader.has_manifest()
                         ? "checksums: all files match manifest.json"
                         : "checksums: not verified");
}

}  // namespace

WIFISLAM_COMMAND(check, 55) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* app = parent.add_subcommand(
      "check",
      "Read a whole dataset (wifislam or plain TUM RGB-D) as SLAM would: verify checksums,\n"
      "decode every image, read the IMU files as the exports do, and print what it holds.\n"
      "Exits non-zero on the first problem.");
  app->add_option("dataset", args->folder, "Dataset folder")->required()->check(kNonEmptyInput);
  app->add_flag("--no-verify", args->no_verify, "Do not compare files with manifest.json");
  app->add_flag("--no-images", args->no_images, "Do not decode images (lists and Wi-Fi only)");
  app->callback([args] { run_check(*args); });
}

}  // namespace wifislam::cli
