#include "tests/sim/render/embree_depth.hpp"

#include <embree3/rtcore.h>

#include <stdexcept>

namespace wifislam::test {

EmbreeDepth::EmbreeDepth(const sim::world::Mesh& mesh) {
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) throw std::runtime_error("Embree device creation failed");
  scene_ = rtcNewScene(device_);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.positions_m.size()));
  for (std::size_t i = 0; i < mesh.positions_m.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions_m[i][k];
  }
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i].v[k];
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
}

EmbreeDepth::~EmbreeDepth() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

cv::Mat EmbreeDepth::depth(const CameraIntrinsics& k, const Pose& camera_to_world, double near_m,
                           double far_m) const {
  cv::Mat out(k.height_px, k.width_px, CV_32FC1, cv::Scalar(0));
  const Eigen::Matrix3d r = camera_to_world.linear();
  const Eigen::Vector3d origin = camera_to_world.translation();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (int v = 0; v < k.height_px; ++v) {
    for (int u = 0; u < k.width_px; ++u) {
      // Direction with optical z = 1: the hit distance t is then the depth along the axis.
      const Eigen::Vector3d dir =
          r * Eigen::Vector3d((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, 1.0);
      RTCRayHit hit{};
      hit.ray.org_x = static_cast<float>(origin.x());
      hit.ray.org_y = static_cast<float>(origin.y());
      hit.ray.org_z = static_cast<float>(origin.z());
      hit.ray.dir_x = static_cast<float>(dir.x());
      hit.ray.dir_y = static_cast<float>(dir.y());
      hit.ray.dir_z = static_cast<float>(dir.z());
      hit.ray.tnear = static_cast<float>(near_m);
      hit.ray.tfar = static_cast<float>(far_m);
      hit.ray.mask = 0xffffffffu;
      hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene_, &context, &hit);
      if (hit.hit.geomID != RTC_INVALID_GEOMETRY_ID) out.at<float>(v, u) = hit.ray.tfar;
    }
  }
  return out;
}

}  // namespace wifislam::test
