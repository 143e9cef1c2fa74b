#pragma once
// A dataset in the EuRoC MAV / ASL layout (the folder ORB-SLAM3's EuRoC examples, OpenVINS's and
// Kalibr's tools read), with the depth images beside the colour camera as RGB-D datasets in that
// layout have them:
//
//   mav0/body.yaml                                the body frame is the IMU's
//   mav0/cam0/data/<ns>.png, data.csv, sensor.yaml   colour images (links), "#timestamp [ns],
//                                                    filename"; T_BS = the camera in the IMU
//                                                    frame, pinhole intrinsics, no distortion
//   mav0/depth0/data/<ns>.png, data.csv, sensor.yaml depth images (links) under the colour
//                                                    image's stamp (registered to cam0), TUM's
//                                                    16-bit PNGs, depth_map_factor 5000
//   mav0/imu0/data.csv, sensor.yaml               imu.csv in nanoseconds, EuRoC's header; the
//                                                    noise parameters of calibration.yaml
//   mav0/state_groundtruth_estimate0/data.csv     imu_groundtruth.csv: the IMU's position,
//                                                    quaternion (w first), velocity and biases
//   timestamps.txt                                the frame stamps in ns, one per line (the
//                                                    times file ORB-SLAM3's EuRoC examples take)
//
// Stamps are integer nanoseconds, EuRoC's. Needs a dataset with an IMU (imu.csv and
// imu_groundtruth.csv, sensors.imu in the scene).

#include <filesystem>
#include <vector>

#include "core/dataset_calibration.hpp"
#include "core/imu_csv.hpp"
#include "core/imu_groundtruth_csv.hpp"
#include "core/tum_file_list.hpp"

namespace wifislam::interop {

/// What the layout is made of, read and checked before anything is written.
struct EurocInput {
  std::vector<FramePair> pairs;
  DatasetCalibration calibration;
  std::vector<ImuReading> imu;
  std::vector<ImuGroundTruth> truth;
};

/// Reads the IMU files. Throws InvalidInputError (exit 2) naming the dataset when it has no IMU.
EurocInput read_euroc_input(const std::filesystem::path& dataset, std::vector<FramePair> pairs,
                            const DatasetCalibration& calibration);

/// Writes the layout into `staging` (its links relative to `final_path`, where it will live).
void write_euroc(const std::filesystem::path& dataset, const EurocInput& input,
                 const std::filesystem::path& final_path, const std::filesystem::path& staging);

}  // namespace wifislam::interop
