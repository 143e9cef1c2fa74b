#include "interop/rtabmap_calibration.hpp"

#include <fmt/format.h>

#include "core/text_lines.hpp"

namespace wifislam::interop {

namespace {

/// A real as FileStorage writes a double ("517.29999999999995", "0."): exact, with a decimal point
/// so that it reads back as a real.
std::string calib_real(double value) {
  std::string text = format_double_exact(value);
  if (text.find_first_of(".eE") == std::string::npos) text += ".";
  return text;
}

/// One "{rows, cols, data}" node, as CameraModel::save writes each matrix.
std::string matrix_node(const char* key, int rows, int cols, const std::string& data) {
  return fmt::format("{}:\n   rows: {}\n   cols: {}\n   data: [ {} ]\n", key, rows, cols, data);
}

}  // namespace

std::string rtabmap_calibration_yaml(const CameraIntrinsics& k) {
  const std::string fx = calib_real(k.fx_px), fy = calib_real(k.fy_px), cx = calib_real(k.cx_px),
                    cy = calib_real(k.cy_px);
  std::string out = "%YAML:1.0\n---\n";
  out += fmt::format("camera_name: {}\n", kRtabmapCameraName);
  out += fmt::format("image_width: {}\nimage_height: {}\n", k.width_px, k.height_px);
  out += matrix_node("camera_matrix", 3, 3,
                     fmt::format("{}, 0., {}, 0., {}, {}, 0., 0., 1.", fx, cx, fy, cy));
  out += matrix_node("distortion_coefficients", 1, 5, "0., 0., 0., 0., 0.");
  out += "distortion_model: plumb_bob\n";
  out += matrix_node("rectification_matrix", 3, 3, "1., 0., 0., 0., 1., 0., 0., 0., 1.");
  out += matrix_node("projection_matrix", 3, 4,
                     fmt::format("{}, 0., {}, 0., 0., {}, {}, 0., 0., 0., 1., 0.", fx, cx, fy, cy));
  // rtabmap-rgbd_dataset's opticalRotation: Transform(0,0,1,0, -1,0,0,0, 0,-1,0,0).
  out += matrix_node("local_transform", 3, 4, "0., 0., 1., 0., -1., 0., 0., 0., 0., -1., 0., 0.");
  return out;
}

}  // namespace wifislam::interop
