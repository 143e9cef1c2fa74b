#include "interop/orbslam2_settings.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/text_lines.hpp"

namespace wifislam::interop {

namespace {

/// A real as TUM1.yaml writes them ("30.0", "517.306408"): exact, always with a decimal point,
/// so FileStorage reads a real where ORB-SLAM2 asks for a float.
std::string real(double value) {
  std::string text = format_double_exact(value);
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

}  // namespace

double depth_baseline_m(const DatasetCalibration& calibration) {
  for (const CalibrationGroup& group : calibration.sensor_model) {
    if (group.name != "depth_sensor") continue;
    for (const auto& [key, value] : group.values) {
      double baseline = 0.0;
      if (key == "baseline_m" && parse_double(value, baseline) && std::isfinite(baseline) &&
          baseline > 0.0) {
        return baseline;
      }
    }
  }
  return kKinectV1BaselineM;
}

std::string orbslam2_settings_yaml(const DatasetCalibration& calibration) {
  const CameraIntrinsics& k = calibration.intrinsics;
  const double baseline_m = depth_baseline_m(calibration);
  std::string out = "%YAML:1.0\n\n";
  out += "# ORB-SLAM2 RGB-D settings (keys of Examples/RGB-D/TUM1.yaml), written by wifislam\n";
  out += "# export from the dataset's calibration.yaml.\n\n";
  out += "# Camera calibration (pinhole; the rendered images have no distortion)\n";
  out += fmt::format("Camera.fx: {}\nCamera.fy: {}\nCamera.cx: {}\nCamera.cy: {}\n\n",
                     real(k.fx_px), real(k.fy_px), real(k.cx_px), real(k.cy_px));
  out += "Camera.k1: 0.0\nCamera.k2: 0.0\nCamera.p1: 0.0\nCamera.p2: 0.0\nCamera.k3: 0.0\n\n";
  out += fmt::format("Camera.width: {}\nCamera.height: {}\n\n", k.width_px, k.height_px);
  out +=
      fmt::format("# Camera frames per second\nCamera.fps: {}\n\n", real(calibration.camera_fps));
  out += fmt::format("# IR projector baseline ({} m) times fx\nCamera.bf: {}\n\n", baseline_m,
                     real(baseline_m * k.fx_px));
  out += "# Color order of the images (0: BGR, 1: RGB), as TUM1.yaml has it for TUM PNGs\n";
  out += "Camera.RGB: 1\n\n";
  out += "# Close/Far threshold. Baseline times.\nThDepth: 40.0\n\n";
  out += fmt::format("# Depth map values per metre\nDepthMapFactor: {}\n\n",
                     real(calibration.depth_units_per_metre));
  out += "# ORB extractor (TUM1.yaml's values)\n";
  out += "ORBextractor.nFeatures: 1000\nORBextractor.scaleFactor: 1.2\nORBextractor.nLevels: 8\n";
  out += "ORBextractor.iniThFAST: 20\nORBextractor.minThFAST: 7\n\n";
  out += "# Viewer (TUM1.yaml's values)\n";
  out += "Viewer.KeyFrameSize: 0.05\nViewer.KeyFrameLineWidth: 1\nViewer.GraphLineWidth: 0.9\n";
  out += "Viewer.PointSize: 2\nViewer.CameraSize: 0.08\nViewer.CameraLineWidth: 3\n";
  out += "Viewer.ViewpointX: 0\nViewer.ViewpointY: -0.7\nViewer.ViewpointZ: -1.8\n";
  out += "Viewer.ViewpointF: 500\n";
  return out;
}

}  // namespace wifislam::interop
