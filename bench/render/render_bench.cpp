// Frame rate of the RGB-D harness (render + readback + sensor model) next to the bare OSMesa cost
// of drawing the same mesh with the same textures and reading colour and depth back, as a ratio
// measured in the same run (DESIGN.md, "Performance stance").
//
// llvmpipe reads LP_NUM_THREADS once per process, so run the program once per thread count:
//   LP_NUM_THREADS=1 render_bench;  LP_NUM_THREADS=2 render_bench
// WIFISLAM_BENCH_LIGHTS=<n> sets RenderOptions::max_lights of the harness (shading cost per light).

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/pose.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/gl_mesh.hpp"
#include "sim/render/gl_program.hpp"
#include "sim/render/gl_texture.hpp"
#include "sim/render/osmesa_context.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/render/test_meshes.hpp"

namespace wifislam {
namespace {

// The workload: a shipped scene's generated world (Arg 0) or the hand-built corridor of the
// tests (Arg 1), seen from poses along the route.
struct Workload {
  Mesh mesh;
  std::vector<CeilingLight> lights;
  std::uint64_t seed = 3;
  std::vector<Pose> poses;
};

const Workload& workload(int which) {
  static const Workload scene_workload = [] {
    Workload w;
    const Scene scene = load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/aliasing_ladder.yaml");
    const World world = generate_world(scene);
    w.mesh = world.mesh;
    w.lights = world.plan.lights;
    w.seed = scene.seed;
    for (std::size_t i = 0; i < world.route.points_m.size();
         i += world.route.points_m.size() / 64) {
      const Eigen::Vector2d p = world.route.points_m[i];
      w.poses.push_back(camera_pose_from_planar(p.x(), p.y(), world.route.heading_rad[i],
                                                scene.sensors.camera.height_m));
    }
    return w;
  }();
  static const Workload corridor_workload = [] {
    Workload w;
    const test::HandCorridor c = test::hand_corridor();
    w.mesh = c.mesh;
    w.lights = c.lights;
    for (int i = 0; i < 64; ++i) {
      const double x = 1.0 + 18.0 * i / 63.0;
      w.poses.push_back(camera_pose_from_planar(
          x, 0.3 * std::sin(i * 0.4),
          (i % 16 < 8 ? 0.0 : std::numbers::pi) + 0.3 * std::sin(i * 0.7), 0.5));
    }
    return w;
  }();
  return which == 0 ? scene_workload : corridor_workload;
}

void record_frame_times(benchmark::State& state, std::vector<double>& frame_ms) {
  std::sort(frame_ms.begin(), frame_ms.end());
  state.counters["median_ms"] = frame_ms[frame_ms.size() / 2];
  state.counters["p90_ms"] = frame_ms[frame_ms.size() * 9 / 10];
}

// The bare loop: same mesh batches and textures, a shader that only samples the texture,
// colour (RGBA8) and window depth (32F) attachments, both read back.
const char* kBareVertex = R"(#version 330 core
layout(location = 0) in vec3 position_m;
layout(location = 2) in vec2 texcoord;
uniform mat4 world_to_clip;
out vec2 uv;
void main() { uv = texcoord; gl_Position = world_to_clip * vec4(position_m, 1.0); }
)";
const char* kBareFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D albedo;
out vec4 color;
void main() { color = texture(albedo, uv); }
)";

void BM_BareOsmesaRenderReadback(benchmark::State& state) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work = workload(static_cast<int>(state.range(0)));
  OsmesaContext context;
  const ProceduralTextures generator(work.seed, AppearanceThemes{});
  std::map<TextureKey, TextureImage> images;
  for (const Triangle& t : work.mesh.triangles) {
    if (!images.contains(texture_key_of(t)))
      images.emplace(texture_key_of(t), generator.make(texture_key_of(t)));
  }
  std::map<TextureKey, std::unique_ptr<GlTexture>> textures;
  for (const auto& [key, image] : images) textures.emplace(key, std::make_unique<GlTexture>(image));
  const GlMesh mesh(batch_mesh(
      work.mesh, [&](const TextureKey& key) -> const TextureImage& { return images.at(key); }));
  const GlProgram program(kBareVertex, kBareFragment);
  GLuint framebuffer = 0, targets[2] = {0, 0};
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glGenRenderbuffers(2, targets);
  glBindRenderbuffer(GL_RENDERBUFFER, targets[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, k.width_px, k.height_px);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, targets[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, targets[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, k.width_px, k.height_px);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, targets[1]);
  glViewport(0, 0, k.width_px, k.height_px);
  glEnable(GL_DEPTH_TEST);
  program.use();
  glUniform1i(program.uniform("albedo"), 0);
  const GLint world_to_clip_location = program.uniform("world_to_clip");
  const std::vector<Pose>& poses = work.poses;
  std::vector<unsigned char> color(4 * static_cast<std::size_t>(k.width_px * k.height_px));
  std::vector<float> depth(static_cast<std::size_t>(k.width_px * k.height_px));
  const Eigen::Matrix4f projection = RgbdRenderer::projection_matrix(k, 0.05, 40.0);
  std::vector<double> frame_ms;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const Eigen::Matrix4f world_to_clip =
        projection * poses[i++ % poses.size()].inverse().matrix().cast<float>();
    glUniformMatrix4fv(world_to_clip_location, 1, GL_FALSE, world_to_clip.data());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mesh.bind();
    for (const MeshBatch& batch : mesh.batches()) {
      textures.at(batch.key)->bind();
      mesh.draw(batch);
    }
    glReadPixels(0, 0, k.width_px, k.height_px, GL_BGRA, GL_UNSIGNED_BYTE, color.data());
    glReadPixels(0, 0, k.width_px, k.height_px, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    benchmark::DoNotOptimize(color.data());
    benchmark::DoNotOptimize(depth.data());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    frame_ms.push_back(ms);
    state.SetIterationTime(ms / 1000.0);
  }
  glDeleteRenderbuffers(2, targets);
  glDeleteFramebuffers(1, &framebuffer);
  record_frame_times(state, frame_ms);
}

void BM_HarnessFrame(benchmark::State& state) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work = workload(static_cast<int>(state.range(0)));
  RenderOptions options;
  if (const char* lights = std::getenv("WIFISLAM_BENCH_LIGHTS"))
    options.max_lights = std::atoi(lights);
  RgbdRenderer renderer(k, options);
  renderer.set_world(work.mesh, work.lights, work.seed, AppearanceThemes{});
  const DepthSensorModel sensor(DepthSensorSpec{}, k, work.seed);
  const bool with_sensor = state.range(1) != 0;
  const std::vector<Pose>& poses = work.poses;
  RenderedView view;
  cv::Mat measured;
  std::vector<double> frame_ms;
  std::int64_t frame = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(poses[frame % static_cast<std::int64_t>(poses.size())], view);
    if (with_sensor) sensor.measure(view.depth_m, view.incidence_cos, frame, measured);
    ++frame;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    frame_ms.push_back(ms);
    state.SetIterationTime(ms / 1000.0);
  }
  record_frame_times(state, frame_ms);
}

void BM_SensorModelOnly(benchmark::State& state) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work = workload(0);
  RgbdRenderer renderer(k);
  renderer.set_world(work.mesh, work.lights, work.seed, AppearanceThemes{});
  const DepthSensorModel sensor(DepthSensorSpec{}, k, work.seed);
  const RenderedView view = renderer.render(work.poses[5]);
  cv::Mat measured;
  std::int64_t frame = 0;
  for (auto _ : state) {
    sensor.measure(view.depth_m, view.incidence_cos, frame++, measured);
    benchmark::DoNotOptimize(measured.data);
  }
}

BENCHMARK(BM_BareOsmesaRenderReadback)
    ->ArgName("corridor")
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(3.0);
BENCHMARK(BM_HarnessFrame)
    ->ArgNames({"corridor", "sensor"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({1, 0})
    ->Args({1, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(3.0);
BENCHMARK(BM_SensorModelOnly)->Unit(benchmark::kMillisecond);

// Keeps each benchmark's median frame time so the ratio can be printed after the run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const auto it = run.counters.find("median_ms");
      if (it != run.counters.end()) median_ms[run.benchmark_name()] = it->second.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> median_ms;
};

}  // namespace
}  // namespace wifislam

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  wifislam::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const char* threads = std::getenv("LP_NUM_THREADS");
  auto median = [&](const std::string& prefix) {
    for (const auto& [name, ms] : reporter.median_ms) {
      if (name.rfind(prefix, 0) == 0) return ms;
    }
    return 0.0;
  };
  for (const char* workload : {"0", "1"}) {
    const double bare = median(std::string("BM_BareOsmesaRenderReadback/corridor:") + workload);
    const double render_only =
        median(std::string("BM_HarnessFrame/corridor:") + workload + "/sensor:0");
    const double full = median(std::string("BM_HarnessFrame/corridor:") + workload + "/sensor:1");
    if (bare <= 0.0 || full <= 0.0) continue;
    std::printf(
        "%s, LP_NUM_THREADS=%s: median frame bare %.2f ms (%.0f fps), harness render only "
        "%.2f ms, harness full %.2f ms (%.0f fps); full / bare = %.2f, render only / bare "
        "= %.2f\n",
        workload[0] == '0' ? "aliasing_ladder scene" : "hand corridor",
        threads ? threads : "(unset: all cores)", bare, 1000.0 / bare, render_only, full,
        1000.0 / full, full / bare, render_only / bare);
  }
  benchmark::Shutdown();
  return 0;
}
