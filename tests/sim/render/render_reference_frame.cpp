#include "core/pose.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "tests/sim/render/render_frame_tool.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam::test {

void render_reference_frame(const std::string& prefix, std::uint64_t seed,
                            std::int64_t frame_index) {
  const HandCorridor corridor = hand_corridor();
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  sim::RgbdRenderer renderer(k);
  renderer.set_world(corridor.mesh, corridor.lights, seed, sim::AppearanceThemes{});
  const sim::RenderedView view =
      renderer.render(camera_pose_from_planar(7.3, -0.4, 0.45, 0.6, 0.05));
  const sim::DepthSensorModel sensor(sim::DepthSensorSpec{}, k, seed);
  sim::write_color_png(prefix + "_rgb.png", view.color_bgr);
  sim::write_depth_png(prefix + "_depth.png", sensor.measure(view, frame_index));
}

}  // namespace wifislam::test
