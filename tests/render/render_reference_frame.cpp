#include "core/pose.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/render/render_frame_tool.hpp"
#include "tests/render/test_meshes.hpp"

namespace wifislam::test {

void render_reference_frame(const std::string& prefix, std::uint64_t seed,
                            std::int64_t frame_index) {
  const HandCorridor corridor = hand_corridor();
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  RgbdRenderer renderer(k);
  renderer.set_world(corridor.mesh, corridor.lights, seed, AppearanceThemes{});
  const RenderedView view = renderer.render(camera_pose_from_planar(7.3, -0.4, 0.45, 0.6, 0.05));
  const DepthSensorModel sensor(DepthSensorSpec{}, k, seed);
  write_color_png(prefix + "_rgb.png", view.color_bgr);
  write_depth_png(prefix + "_depth.png", sensor.measure(view, frame_index));
}

}  // namespace wifislam::test
