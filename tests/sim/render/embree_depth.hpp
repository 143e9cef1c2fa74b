#pragma once
// Depth images by Embree 3 ray casting: the second, independent engine the renderer's depth is
// checked against.

#include <opencv2/core.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "sim/world/world_types.hpp"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace wifislam::test {

class EmbreeDepth {
 public:
  explicit EmbreeDepth(const sim::world::Mesh& mesh);
  ~EmbreeDepth();
  EmbreeDepth(const EmbreeDepth&) = delete;
  EmbreeDepth& operator=(const EmbreeDepth&) = delete;

  /// Depth along the optical axis of the first hit through each pixel centre, 0 where the ray
  /// hits nothing closer than `far_m`.
  cv::Mat depth(const CameraIntrinsics& intrinsics, const Pose& camera_to_world, double near_m,
                double far_m) const;

 private:
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
};

}  // namespace wifislam::test
