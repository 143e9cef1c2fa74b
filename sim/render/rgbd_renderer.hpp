#pragma once
// Off-screen RGB-D rendering of a world mesh through a pinhole camera (OSMesa, OpenGL 3.3 core).
//
// One OpenGL context per renderer, reused for every frame. A frame renders into a framebuffer
// object with an RGBA8 target (lit colour, and in alpha |cos| of the angle between viewing ray and
// surface, for the sensor model's grazing-angle dropouts) and a 32-bit float z-buffer, from which
// metric depth along the optical axis is recovered exactly (see unpack()). That is the same
// readback a bare render needs; extra float targets cost ~40 % of the frame in llvmpipe. The
// intrinsics go straight into the projection matrix, with y flipped so that readback row 0 is
// image row v = 0 and pixel (u, v) is sampled at its centre, as in OpenCV.
//
// Noise-free output: DepthSensorModel turns the ideal depth into a Kinect-like measurement.

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera_intrinsics.hpp"
#include "core/pose.hpp"
#include "sim/render/procedural_textures.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim::render {

class OsmesaContext;
class GlMesh;
class GlTexture;
class GlProgram;

struct RenderOptions {
  double near_m = 0.05;         // closer surfaces are clipped (below any depth sensor's range)
  double far_m = 40.0;          // farther surfaces are not drawn
  float ambient = 0.45f;        // light every surface gets, as a fraction of its albedo
  float light_power = 2.5f;     // one ceiling light's irradiance at 1 m, times (d^2 + 1)
  int max_lights = 2;           // nearest lights shaded per frame (0..8): each adds shading cost
  double light_range_m = 12.0;  // lights farther from the camera are not shaded
  double light_fade_m = 1.5;    // lights fade out over this distance before they drop out
  bool frustum_culling = true;  // skip mesh chunks outside the view
  double chunk_m = 6.0;         // mesh batches are cut into plan chunks this size for culling
};

/// The noise-free result of one render.
struct RenderedView {
  cv::Mat color_bgr;      // CV_8UC3, OpenCV channel order
  cv::Mat depth_m;        // CV_32FC1, along the optical axis, 0 = nothing within far_m
  cv::Mat incidence_cos;  // CV_32FC1, |cos| between viewing ray and surface normal (steps of
                          // 1/255), 0 = nothing
};

class RgbdRenderer {
 public:
  /// Creates the context, shaders and framebuffer. Throws EnvironmentError when OSMesa or
  /// OpenGL 3.3 is missing, InvalidInputError for bad intrinsics.
  explicit RgbdRenderer(const CameraIntrinsics& intrinsics, const RenderOptions& options = {});
  ~RgbdRenderer();
  RgbdRenderer(const RgbdRenderer&) = delete;
  RgbdRenderer& operator=(const RgbdRenderer&) = delete;

  /// Uploads a world: its mesh, ceiling lights, and textures generated from the seed and themes
  /// (one per distinct texture key in the mesh). Replaces any previous world.
  void set_world(const world::Mesh& mesh, const std::vector<world::CeilingLight>& lights,
                 std::uint64_t seed, const scene::AppearanceThemes& themes);
  /// The same for a generated world and its scene (seed, themes).
  void set_world(const world::World& world, const scene::Scene& scene);

  /// Renders the view of a camera-to-world pose (optical frame). Reuses `out`'s buffers.
  /// The same as submit() then collect().
  void render(const Pose& camera_to_world, RenderedView& out);
  RenderedView render(const Pose& camera_to_world);
  /// The two halves of render(), for callers that have other work while a frame rasterizes:
  /// submit() draws the view and hands it to the rasterizer (llvmpipe's threads) and returns;
  /// collect() waits for it and reads it back. The pixels are the same as render()'s. One view
  /// at a time: submit() again before collect() (or collect() without submit()) throws
  /// std::logic_error.
  void submit(const Pose& camera_to_world);
  void collect(RenderedView& out);
  /// Whether a submitted view awaits collect().
  bool has_submitted() const { return submitted_; }

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const RenderOptions& options() const { return options_; }
  const OsmesaContext& context() const { return *context_; }
  std::size_t texture_count() const { return textures_.size(); }
  /// Batches drawn by the last render (after frustum culling).
  int last_draw_count() const { return last_draw_count_; }

  /// Projection matrix of the intrinsics (camera optical frame -> clip space, y flipped).
  static Eigen::Matrix4f projection_matrix(const CameraIntrinsics& intrinsics, double near_m,
                                           double far_m);

 private:
  void upload_lights(const Eigen::Vector3d& camera_position_m);
  /// Read-back values -> colour, metric depth and incidence images, in place: out.depth_m holds
  /// the z-buffer in [0, 1], out.incidence_cos the BGRA bytes (alpha = incidence |cos| x 255).
  void unpack(RenderedView& out) const;

  CameraIntrinsics intrinsics_;
  RenderOptions options_;
  std::unique_ptr<OsmesaContext> context_;
  std::unique_ptr<GlProgram> program_;
  std::unique_ptr<GlMesh> mesh_;
  std::map<TextureKey, std::unique_ptr<GlTexture>> textures_;
  std::vector<world::CeilingLight> lights_;
  unsigned framebuffer_ = 0, color_target_ = 0, z_buffer_ = 0;
  int last_draw_count_ = 0;
  bool submitted_ = false;
  struct Uniforms {
    int world_to_clip, camera_position, emissive, ambient, light_weights, light_positions, albedo;
  } uniforms_{};
};

}  // namespace wifislam::sim::render
