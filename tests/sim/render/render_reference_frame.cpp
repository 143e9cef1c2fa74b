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
  sim::render::RgbdRenderer renderer(k);
  renderer.set_world(corridor.mesh, corridor.lights, seed, sim::scene::AppearanceThemes{});
  const sim::render::RenderedView view =
      renderer.render(camera_pose_from_planar(7.3, -0.4, 0.45, 0.6, 0.05));
  const sim::render::DepthSensorModel sensor(sim::scene::DepthSensorSpec{}, k, seed);
  sim::render::write_color_png(prefix + "_rgb.png", view.color_bgr);
  sim::render::write_depth_png(prefix + "_depth.png", sensor.measure(view, frame_index));
}

}  // namespace wifislam::test
