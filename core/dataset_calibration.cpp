#include "core/dataset_calibration.hpp"

#include <cmath>

#include <yaml-cpp/yaml.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"
#include "core/yaml_document.hpp"

namespace wifislam {

std::string calibration_to_yaml(const DatasetCalibration& c) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  auto number = [&](double v) { out << YAML::Value << format_double_exact(v); };
  out << YAML::Comment("wifislam dataset calibration") << YAML::BeginMap;
  out << YAML::Key << "camera" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "width_px" << YAML::Value << c.intrinsics.width_px;
  out << YAML::Key << "height_px" << YAML::Value << c.intrinsics.height_px;
  out << YAML::Key << "fx_px";
  number(c.intrinsics.fx_px);
  out << YAML::Key << "fy_px";
  number(c.intrinsics.fy_px);
  out << YAML::Key << "cx_px";
  number(c.intrinsics.cx_px);
  out << YAML::Key << "cy_px";
  number(c.intrinsics.cy_px);
  out << YAML::Key << "fps";
  number(c.camera_fps);
  out << YAML::EndMap;
  out << YAML::Key << "depth" << YAML::Value << YAML::BeginMap << YAML::Key << "units_per_metre";
  number(c.depth_units_per_metre);
  out << YAML::EndMap;
  auto pose_map = [&](const char* key, const char* comment, const Pose& pose) {
    const Eigen::Quaterniond q(pose.linear());
    out << YAML::Key << key << YAML::Comment(comment) << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "translation_m" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (int i = 0; i < 3; ++i) out << format_double_exact(pose.translation()[i]);
    out << YAML::EndSeq;
    out << YAML::Key << "rotation_xyzw" << YAML::Value << YAML::Flow << YAML::BeginSeq
        << format_double_exact(q.x()) << format_double_exact(q.y()) << format_double_exact(q.z())
        << format_double_exact(q.w()) << YAML::EndSeq;
    out << YAML::EndMap;
  };
  pose_map("camera_in_base", "camera optical frame in the robot base", c.camera_in_base);
  if (c.odometry_rate_hz) {
    out << YAML::Key << "odometry" << YAML::Value << YAML::BeginMap << YAML::Key << "rate_hz";
    number(*c.odometry_rate_hz);
    out << YAML::EndMap;
  }
  if (c.imu) {
    const ImuCalibration& imu = *c.imu;
    out << YAML::Key << "imu" << YAML::Comment("imu.csv") << YAML::Value << YAML::BeginMap
        << YAML::Key << "rate_hz";
    number(imu.rate_hz);
    pose_map("imu_in_base", "IMU frame in the robot base", imu.imu_in_base);
    out << YAML::Key << "T_cam_imu"
        << YAML::Comment("IMU frame to camera optical frame, 4x4 row-major (Kalibr)") << YAML::Value
        << YAML::Flow << YAML::BeginSeq;
    const Eigen::Matrix4d t = c.camera_from_imu().matrix();
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col) out << format_double_exact(t(r, col));
    out << YAML::EndSeq;
    for (const auto& [key, value] :
         {std::pair{"gyroscope_noise_density", imu.gyroscope_noise_density},
          std::pair{"gyroscope_random_walk", imu.gyroscope_random_walk},
          std::pair{"accelerometer_noise_density", imu.accelerometer_noise_density},
          std::pair{"accelerometer_random_walk", imu.accelerometer_random_walk}}) {
      out << YAML::Key << key;
      number(value);
    }
    out << YAML::EndMap;
  }
  if (!c.sensor_model.empty()) {
    out << YAML::Key << "sensor_model" << YAML::Value << YAML::BeginMap;
    for (const CalibrationGroup& g : c.sensor_model) {
      out << YAML::Key << g.name << YAML::Value << YAML::BeginMap;
      for (const auto& [key, value] : g.values) out << YAML::Key << key << YAML::Value << value;
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

namespace {

struct Ctx {
  std::string file;
  std::string where(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    if (m.line < 0) return file;
    return fmt::format("{}:{}:{}", file, m.line + 1, m.column + 1);
  }
};

YAML::Node child(const Ctx& ctx, const YAML::Node& parent, const char* key, const std::string& path,
                 bool required) {
  if (!parent.IsMap()) {
    throw ParseError(ctx.where(parent), path.empty() ? std::string(key) : path,
                     "expected a mapping (key: value lines)");
  }
  const YAML::Node n = parent[key];
  if (!n && required)
    throw ParseError(ctx.where(parent), path + "." + key, std::string("missing key '") + key + "'");
  return n;
}

double number(const Ctx& ctx, const YAML::Node& n, const std::string& path) {
  double v = 0;
  if (!n.IsScalar() || !parse_double(n.Scalar(), v))
    throw ParseError(ctx.where(n), path, "expected a number");
  return v;
}

/// {translation_m: [x, y, z], rotation_xyzw: [x, y, z, w]} under `path`.
Pose read_pose(const Ctx& ctx, const YAML::Node& node, const std::string& path) {
  const YAML::Node t = child(ctx, node, "translation_m", path, true);
  const YAML::Node q = child(ctx, node, "rotation_xyzw", path, true);
  if (!t.IsSequence() || t.size() != 3)
    throw ParseError(ctx.where(t), path + ".translation_m", "expected [x, y, z]");
  if (!q.IsSequence() || q.size() != 4)
    throw ParseError(ctx.where(q), path + ".rotation_xyzw", "expected [x, y, z, w]");
  Eigen::Vector3d tv;
  for (int i = 0; i < 3; ++i) tv[i] = number(ctx, t[i], path + ".translation_m");
  double qv[4];
  for (int i = 0; i < 4; ++i) qv[i] = number(ctx, q[i], path + ".rotation_xyzw");
  const Eigen::Quaterniond quat(qv[3], qv[0], qv[1], qv[2]);
  if (!(quat.norm() >= 1e-6))
    throw ParseError(ctx.where(q), path + ".rotation_xyzw", "quaternion has zero length");
  return pose_from_translation_quaternion(tv, quat);
}

}  // namespace

DatasetCalibration read_calibration_yaml(const std::filesystem::path& path) {
  const Ctx ctx{path.string()};
  const YAML::Node root = load_yaml_file(path.string());
  if (!root.IsMap()) throw ParseError(path.string(), "", "expected a YAML mapping");
  DatasetCalibration c;
  const YAML::Node cam = child(ctx, root, "camera", "", true);
  auto cam_number = [&](const char* key) {
    return number(ctx, child(ctx, cam, key, "camera", true), std::string("camera.") + key);
  };
  // Image sizes are whole pixels; 65535 bounds them far above any depth camera.
  auto cam_pixels = [&](const char* key) {
    const double v = cam_number(key);
    if (!(v >= 1 && v <= 65535 && v == std::floor(v))) {
      throw ParseError(ctx.where(cam[key]), std::string("camera.") + key,
                       "expected a whole number of pixels from 1 to 65535");
    }
    return static_cast<int>(v);
  };
  c.intrinsics.width_px = cam_pixels("width_px");
  c.intrinsics.height_px = cam_pixels("height_px");
  c.intrinsics.fx_px = cam_number("fx_px");
  c.intrinsics.fy_px = cam_number("fy_px");
  c.intrinsics.cx_px = cam_number("cx_px");
  c.intrinsics.cy_px = cam_number("cy_px");
  // Physically meaningful values only: exports copy them into other programs' settings (ORB-SLAM's
  // Camera.fx, EuRoC's rate_hz), which would take 1e308 or a negative rate without a word.
  if (const std::optional<IntrinsicsProblem> problem = intrinsics_problem(c.intrinsics))
    throw ParseError(ctx.where(cam[problem->key]), "camera." + problem->key, problem->why);
  if (const YAML::Node fps = child(ctx, cam, "fps", "camera", false)) {
    c.camera_fps = number(ctx, fps, "camera.fps");
    // Up to what `generate --fps` accepts.
    if (!(c.camera_fps > 0 && c.camera_fps <= 1000))
      throw ParseError(ctx.where(fps), "camera.fps", "expected a frame rate above 0, up to 1000");
  }
  if (const YAML::Node depth = child(ctx, root, "depth", "", false)) {
    const YAML::Node units = child(ctx, depth, "units_per_metre", "depth", true);
    c.depth_units_per_metre = number(ctx, units, "depth.units_per_metre");
    // A 16-bit PNG holds depths up to 65535 units: beyond 65535 units a metre, not even 1 m.
    if (!(c.depth_units_per_metre > 0 && c.depth_units_per_metre <= 65535))
      throw ParseError(
          ctx.where(units), "depth.units_per_metre",
          "expected a scale above 0, up to 65535 (16-bit depth: at least 1 m of range)");
  }
  if (const YAML::Node mount = child(ctx, root, "camera_in_base", "", false))
    c.camera_in_base = read_pose(ctx, mount, "camera_in_base");
  if (const YAML::Node odo = child(ctx, root, "odometry", "", false)) {
    const YAML::Node rate = child(ctx, odo, "rate_hz", "odometry", true);
    c.odometry_rate_hz = number(ctx, rate, "odometry.rate_hz");
    if (!(*c.odometry_rate_hz > 0 && *c.odometry_rate_hz <= 1e4))
      throw ParseError(ctx.where(rate), "odometry.rate_hz",
                       "expected a rate above 0, up to 10000 Hz");
  }
  if (const YAML::Node imu = child(ctx, root, "imu", "", false)) {
    ImuCalibration i;
    auto positive = [&](const char* key) {
      const YAML::Node n = child(ctx, imu, key, "imu", true);
      const double v = number(ctx, n, std::string("imu.") + key);
      if (!(v >= 0.0 && std::isfinite(v)))
        throw ParseError(ctx.where(n), std::string("imu.") + key, "must be a finite number >= 0");
      return v;
    };
    i.rate_hz = positive("rate_hz");
    if (!(i.rate_hz > 0.0 && i.rate_hz <= 1e5))
      throw ParseError(ctx.where(imu["rate_hz"]), "imu.rate_hz",
                       "expected a rate above 0, up to 100000 Hz");
    i.imu_in_base = read_pose(ctx, child(ctx, imu, "imu_in_base", "imu", true), "imu.imu_in_base");
    i.gyroscope_noise_density = positive("gyroscope_noise_density");
    i.gyroscope_random_walk = positive("gyroscope_random_walk");
    i.accelerometer_noise_density = positive("accelerometer_noise_density");
    i.accelerometer_random_walk = positive("accelerometer_random_walk");
    c.imu = i;
  }
  if (const YAML::Node model = child(ctx, root, "sensor_model", "", false)) {
    if (!model.IsMap()) throw ParseError(ctx.where(model), "sensor_model", "expected a mapping");
    for (const auto& group : model) {
      CalibrationGroup g;
      g.name = group.first.Scalar();
      if (!group.second.IsMap()) {
        throw ParseError(ctx.where(group.second), "sensor_model." + g.name, "expected a mapping");
      }
      for (const auto& kv : group.second) {
        if (!kv.first.IsScalar() || !kv.second.IsScalar())
          throw ParseError(ctx.where(kv.second), "sensor_model." + g.name, "expected scalars");
        g.values.emplace_back(kv.first.Scalar(), kv.second.Scalar());
      }
      c.sensor_model.push_back(std::move(g));
    }
  }
  return c;
}

}  // namespace wifislam
