#include "interop/euroc_export.hpp"

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/stop_signal.hpp"
#include "core/text_lines.hpp"
#include "interop/relative_link.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

/// A 4x4 matrix as EuRoC's sensor.yaml writes T_BS.
std::string euroc_matrix(const Pose& pose) {
  const Eigen::Matrix4d m = pose.matrix();
  std::string rows;
  for (int r = 0; r < 4; ++r) {
    rows += r == 0 ? "  data: [" : "         ";
    for (int c = 0; c < 4; ++c) {
      rows += format_double_exact(m(r, c) + 0.0);  // no "-0"
      rows += (r == 3 && c == 3) ? "]\n" : (c == 3 ? ",\n" : ", ");
    }
  }
  return "T_BS:\n  cols: 4\n  rows: 4\n" + rows;
}

std::string camera_sensor_yaml(const char* comment, const DatasetCalibration& c,
                               const Pose& camera_in_body, const std::string& extra) {
  const CameraIntrinsics& k = c.intrinsics;
  std::string y = "# General sensor definitions.\nsensor_type: camera\n";
  y += fmt::format("comment: {}\n\n# Sensor extrinsics wrt. the body-frame.\n", comment);
  y += euroc_matrix(camera_in_body);
  y += "\n# Camera specific definitions.\n";
  y += fmt::format("rate_hz: {}\nresolution: [{}, {}]\ncamera_model: pinhole\n",
                   format_double_exact(c.camera_fps), k.width_px, k.height_px);
  y += fmt::format("intrinsics: [{}, {}, {}, {}] #fu, fv, cu, cv\n", format_double_exact(k.fx_px),
                   format_double_exact(k.fy_px), format_double_exact(k.cx_px),
                   format_double_exact(k.cy_px));
  y += "distortion_model: radial-tangential\ndistortion_coefficients: [0, 0, 0, 0]\n";
  return y + extra;
}

std::string imu_sensor_yaml(const ImuCalibration& imu) {
  std::string y = "#Default imu sensor yaml file\nsensor_type: imu\n";
  y += "comment: wifislam simulated IMU (sim/robot/imu_model.hpp)\n\n";
  y += "# Sensor extrinsics wrt. the body-frame.\n" + euroc_matrix(Pose::Identity());
  y += fmt::format("rate_hz: {}\n\n# inertial sensor noise model parameters (static)\n",
                   format_double_exact(imu.rate_hz));
  const std::pair<const char*, double> noise[] = {
      {"gyroscope_noise_density: {}     # [ rad / s / sqrt(Hz) ]   ( gyro \"white noise\" )\n",
       imu.gyroscope_noise_density},
      {"gyroscope_random_walk: {}       # [ rad / s^2 / sqrt(Hz) ] ( gyro bias diffusion )\n",
       imu.gyroscope_random_walk},
      {"accelerometer_noise_density: {}  # [ m / s^2 / sqrt(Hz) ]   ( accel \"white noise\" )\n",
       imu.accelerometer_noise_density},
      {"accelerometer_random_walk: {}    # [ m / s^3 / sqrt(Hz) ].  ( accel bias diffusion )\n",
       imu.accelerometer_random_walk}};
  for (const auto& [line, value] : noise)
    y += fmt::format(fmt::runtime(line), format_double_exact(value));
  return y;
}

constexpr const char* kGroundTruthSensorYaml =
    "# Additional sensor information\nsensor_type: visual-inertial\n"
    "comment: wifislam exact ground truth of the IMU (imu_groundtruth.csv) at the frame times\n\n"
    "# Sensor extrinsics wrt. the body-frame.\n"
    "T_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0,\n         0, 1, 0, 0,\n"
    "         0, 0, 1, 0,\n         0, 0, 0, 1]\n";

std::string ns(Timestamp t) { return std::to_string(t.ns); }

}  // namespace

EurocInput read_euroc_input(const fs::path& dataset, std::vector<FramePair> pairs,
                            const DatasetCalibration& calibration) {
  if (!calibration.imu || !fs::exists(dataset / dataset::kImu) ||
      !fs::exists(dataset / dataset::kImuGroundTruth)) {
    throw InvalidInputError(fmt::format(
        "{}: has no IMU (calibration.yaml without imu, or no {} and {}), which the EuRoC layout "
        "needs: generate it again with sensors.imu enabled (the default)",
        dataset.string(), dataset::kImu, dataset::kImuGroundTruth));
  }
  for (const FramePair& p : pairs) {
    if (p.rgb_time.ns < 0) {
      throw InvalidInputError(
          fmt::format("{}: frame time {} is negative; EuRoC names frames by unsigned nanoseconds",
                      dataset.string(), p.rgb_time.to_tum_string()));
    }
  }
  EurocInput input;
  input.pairs = std::move(pairs);
  input.calibration = calibration;
  input.imu = read_imu_csv((dataset / dataset::kImu).string());
  input.truth = read_imu_groundtruth_csv((dataset / dataset::kImuGroundTruth).string());
  return input;
}

void write_euroc(const fs::path& dataset, const EurocInput& input, const fs::path& final_path,
                 const fs::path& staging) {
  const fs::path mav = staging / "mav0";
  for (const char* sensor : {"cam0/data", "depth0/data", "imu0", "state_groundtruth_estimate0"})
    fs::create_directories(mav / sensor);
  const DatasetCalibration& c = input.calibration;
  // The body frame is the IMU's: cam0's T_BS is the camera in the IMU frame (inverse T_cam_imu).
  const Pose camera_in_imu = c.camera_from_imu().inverse();

  std::string cam_csv = "#timestamp [ns],filename\n", depth_csv = cam_csv, times;
  for (const FramePair& p : input.pairs) {
    throw_if_stop_requested();  // `export`: Ctrl-C removes the unfinished folder
    const std::string name = ns(p.rgb_time) + ".png";
    link_relative(dataset / p.rgb_path, final_path / "mav0/cam0/data" / name,
                  mav / "cam0/data" / name);
    link_relative(dataset / p.depth_path, final_path / "mav0/depth0/data" / name,
                  mav / "depth0/data" / name);
    cam_csv += ns(p.rgb_time) + "," + name + "\n";
    depth_csv += ns(p.rgb_time) + "," + name + "\n";
    times += ns(p.rgb_time) + "\n";
  }
  write_file_atomic(mav / "cam0/data.csv", cam_csv);
  write_file_atomic(mav / "depth0/data.csv", depth_csv);
  write_file_atomic(staging / "timestamps.txt", times);
  write_file_atomic(mav / "cam0/sensor.yaml",
                    camera_sensor_yaml("wifislam RGB-D colour camera", c, camera_in_imu, ""));
  write_file_atomic(
      mav / "depth0/sensor.yaml",
      camera_sensor_yaml("wifislam depth images registered to cam0 (same stamps, same pixels)", c,
                         camera_in_imu,
                         fmt::format("depth_map_factor: {}  # depth PNG units per metre, 0 = no "
                                     "reading\n",
                                     format_double_exact(c.depth_units_per_metre))));

  std::string imu_csv =
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
      "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n";
  for (const ImuReading& r : input.imu) {
    const Eigen::Vector3d& w = r.angular_velocity_radps;
    const Eigen::Vector3d& a = r.specific_force_mps2;
    imu_csv += fmt::format("{},{},{},{},{},{},{}\n", ns(r.time), format_double_exact(w.x()),
                           format_double_exact(w.y()), format_double_exact(w.z()),
                           format_double_exact(a.x()), format_double_exact(a.y()),
                           format_double_exact(a.z()));
  }
  write_file_atomic(mav / "imu0/data.csv", imu_csv);
  write_file_atomic(mav / "imu0/sensor.yaml", imu_sensor_yaml(*c.imu));

  std::string truth_csv =
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], "
      "q_RS_z [], v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], "
      "b_w_RS_S_y [rad s^-1], b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], "
      "b_a_RS_S_z [m s^-2]\n";
  for (const ImuGroundTruth& s : input.truth) {
    const Eigen::Vector3d& p = s.imu_to_world.translation();
    const Eigen::Quaterniond q(s.imu_to_world.linear());
    std::string row = ns(s.time);
    for (double v :
         {p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z(), s.velocity_mps.x(), s.velocity_mps.y(),
          s.velocity_mps.z(), s.gyro_bias_radps.x(), s.gyro_bias_radps.y(), s.gyro_bias_radps.z(),
          s.accel_bias_mps2.x(), s.accel_bias_mps2.y(), s.accel_bias_mps2.z()})
      row += "," + format_double_exact(v);
    truth_csv += row + "\n";
  }
  write_file_atomic(mav / "state_groundtruth_estimate0/data.csv", truth_csv);
  write_file_atomic(mav / "state_groundtruth_estimate0/sensor.yaml", kGroundTruthSensorYaml);
  write_file_atomic(mav / "body.yaml", "comment: 'The body frame is the IMU frame (imu0).'\n");
}

}  // namespace wifislam::interop
