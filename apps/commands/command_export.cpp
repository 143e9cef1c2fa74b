// `wifislam export <dataset> --for rtabmap|orbslam2|euroc|kapture|rosbag -o <dir>`: lay a dataset
// out the way another SLAM system's own dataset tool reads one, with links to the dataset's images
// (interop/).
#include <memory>
#include <string>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/output_folder.hpp"
#include "core/stop_signal.hpp"
#include "interop/peer_export.hpp"

namespace wifislam::cli {

namespace {

struct ExportArgs {
  std::string dataset;
  std::string peer;
  std::string output;
  bool force = false;
  bool no_verify = false;
  bool quiet = false;
};

void run_export(const ExportArgs& args) {
  const bool replace = check_output_folder({args.output, args.force, {}, {args.dataset}});
  interop::PeerExportOptions options;
  options.peer = *interop::peer_from_string(args.peer);  // CLI11 checked the name
  options.verify_checksums = !args.no_verify;
  options.overwrite = replace;
  const StopOnSignal stop_on_signal;  // Ctrl-C removes the unfinished export
  const interop::PeerExportSummary summary =
      interop::export_for_peer(args.dataset, args.output, options);
  if (!args.quiet) fmt::print("{}", summary.full_report());
  for (const std::string& w : summary.warnings) fmt::print(stderr, "wifislam: warning: {}\n", w);
}

}  // namespace

WIFISLAM_COMMAND(export, 58) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* app = parent.add_subcommand(
      "export",
      "Lay a dataset (wifislam or plain TUM RGB-D) out the way another SLAM system's own dataset\n"
      "tool reads one. Images are relative symbolic links to the dataset's files, not copies,\n"
      "so keep (or move, or mount) the dataset and the export together; a ROS bag (--for\n"
      "rosbag) carries the images' bytes instead.");
  app->footer(
      "--for rtabmap: for RTAB-Map's `rtabmap-rgbd_dataset DIR`:\n"
      "  rgb_sync/<t>.png and depth_sync/<t>.png  every associated pair, both under the rgb\n"
      "                                           stamp <t> (the tool reads times from the names)\n"
      "  groundtruth.txt                          link to the dataset's\n"
      "  rtabmap_calib.yaml                       the dataset's intrinsics in RTAB-Map's own\n"
      "                                           calibration format (CameraModel: camera_matrix,\n"
      "                                           projection_matrix, local_transform, ...)\n"
      "  The tool prints 'Dataset DIR is not supported' and then reads rtabmap_calib.yaml,\n"
      "  whatever DIR is called, unless DIR's name holds 'freiburg1', 'freiburg2' or\n"
      "  'freiburg3': then it writes that TUM Kinect's calibration over ours (fr1 fx 517.3 fy\n"
      "  516.5 cx 318.6 cy 255.3; fr2 520.9 521.0 325.1 249.7; fr3 535.4 539.2 320.1 247.6), and\n"
      "  the export warns when that is not the dataset's camera. Stamps must be positive:\n"
      "  datasets generated before the time origin (scenes' sensors.time_origin_s) start at 0\n"
      "  and are refused.\n"
      "--for orbslam2: for ORB-SLAM2's `rgbd_tum VOCABULARY DIR/orbslam2_settings.yaml DIR\n"
      "  DIR/associations.txt`:\n"
      "  rgb/<t>.png, depth/<t>.png               links under each image's own stamp\n"
      "  associations.txt                         't_rgb rgb/<t>.png t_depth depth/<t>.png', as\n"
      "                                           TUM's associate.py writes it, paths in DIR\n"
      "  orbslam2_settings.yaml                   TUM1.yaml's keys with the dataset's intrinsics,\n"
      "                                           no distortion, its fps, Camera.bf = depth\n"
      "                                           baseline (Kinect v1: 0.075 m) x fx, Camera.RGB\n"
      "                                           1, ThDepth 40, DepthMapFactor 5000 (the\n"
      "                                           dataset's units per metre), ORB extractor and\n"
      "                                           viewer defaults\n"
      "  groundtruth.txt                          link to the dataset's\n"
      "--for euroc: the EuRoC MAV / ASL layout (ORB-SLAM3's EuRoC examples, OpenVINS, Kalibr),\n"
      "  for datasets with an IMU (imu.csv; sensors.imu, on by default):\n"
      "  mav0/cam0/data/<ns>.png, data.csv, sensor.yaml  colour images, T_BS = camera in the IMU\n"
      "                                           frame, pinhole intrinsics\n"
      "  mav0/depth0/...                          depth PNGs under the colour stamps,\n"
      "                                           depth_map_factor 5000\n"
      "  mav0/imu0/data.csv, sensor.yaml          the IMU in ns, its noise parameters\n"
      "  mav0/state_groundtruth_estimate0/data.csv  the IMU's pose, velocity and biases\n"
      "  timestamps.txt                           frame stamps in ns (ORB-SLAM3's times file)\n"
      "--for kapture: a Kapture 1.1 folder: sensors.txt, rigs.txt, trajectories.txt (world to\n"
      "  rig), records_camera.txt (image links), records_depth.txt (float32 .depth files,\n"
      "  converted), records_wifi.txt (LaMAR's Wi-Fi columns, MHz) and, with an IMU,\n"
      "  records_accelerometer.txt and records_gyroscope.txt; integer microsecond stamps.\n"
      "--for rosbag: one ROS 1 bag, DIR/dataset.bag (LZ4 chunks), with the TUM RGB-D bags'\n"
      "  topics: /camera/rgb/image_color (rgb8), /camera/depth/image (32FC1 metres, NaN = no\n"
      "  reading), both camera_info, /tf (world -> kinect ground truth, odom -> base_link),\n"
      "  /tf_static (base_link -> camera, imu_link); and /imu (sensor_msgs/Imu), /odom (wheel\n"
      "  odometry), /ground_truth/pose (geometry_msgs/PoseStamped) and /wifi/scan\n"
      "  (wifislam_msgs/WifiScan, its definition in the bag). ROS 2: `rosbags-convert`.\n"
      "Every layout writes export.json (what was exported, the TUM camera match, warnings, the\n"
      "command to run). rtabmap and orbslam2 name frames by their stamps as TUM writes them (6\n"
      "decimals, 9 when finer). Score the peer's trajectory with `wifislam eval\n"
      "CameraTrajectory.txt --gt DATASET`.\n"
      "DIR is written as DIR.partial and renamed when complete; it is never inside or around the\n"
      "dataset. Exit 2 for a dataset without images, frames sharing a stamp, (rtabmap, rosbag) a\n"
      "stamp that is not positive, (euroc) a dataset without an IMU, (kapture, rosbag) one\n"
      "without ground truth.");
  app->add_option("dataset", args->dataset, "Dataset folder")->required()->check(kNonEmptyInput);
  app->add_option("--for", args->peer, "The peer whose dataset tool reads the export")
      ->required()
      ->check(CLI::IsMember(interop::peer_names()));
  app->add_option("-o,--output", args->output, "Folder to create")->required();
  app->add_flag("--force", args->force,
                "Replace the output folder if it holds this tool's output (a previous export,\n"
                "with whatever a peer wrote into it, such as rtabmap.db); never the dataset, the\n"
                "current directory, the home folder or a folder of your own");
  app->add_flag("--no-verify", args->no_verify, "Do not check the dataset's SHA-256 sums");
  app->add_flag("-q,--quiet", args->quiet, "Print nothing but warnings on success");
  app->callback([args] { run_export(*args); });
}

}  // namespace wifislam::cli
