// Frame time of the RGB-D harness (render + readback + sensor model) next to the bare OSMesa cost
// of drawing the same mesh with the same textures and reading colour and depth back, as a ratio
// measured in the same run (docs/benchmarks.md). Counters, all medians over frames:
// bare_ms, render_ms (harness render + readback + unpack), sensor_ms, frame_ms (render + sensor),
// frame_over_bare (the issue's target: <= 1.3) and render_over_bare.
// BM_PipelinedVsBare: the same in stretches of consecutive frames, one frame after the other
// (serial_over_bare) and with the next frame submitted before the sensor model runs, as the
// generator does (pipelined_over_bare: the throughput a long run sees).
// bench/render/run.sh runs it with 1 and 2 llvmpipe threads and 5 repetitions.
// BM_SensorModelOnly and BM_ColorSensorModelOnly time the depth and colour sensor models alone,
// with their off-by-default parts off and on.
// WIFISLAM_BENCH_LIGHTS=<n> sets RenderOptions::max_lights of the harness (shading cost per light).
//
// llvmpipe reads LP_NUM_THREADS once per process, so run the program once per thread count:
//   LP_NUM_THREADS=1 render_bench;  LP_NUM_THREADS=2 render_bench

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
#include "sim/render/color_sensor_model.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/gl_mesh.hpp"
#include "sim/render/gl_program.hpp"
#include "sim/render/gl_texture.hpp"
#include "sim/render/osmesa_context.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"
#include "tests/sim/render/test_meshes.hpp"

namespace wifislam {
namespace {

// The workload: a shipped scene's generated world (Arg 0) or the hand-built corridor of the
// tests (Arg 1), seen from poses along the route.
struct Workload {
  sim::world::Mesh mesh;
  std::vector<sim::world::CeilingLight> lights;
  std::uint64_t seed = 3;
  std::vector<Pose> poses;
};

const Workload& workload(int which) {
  static const Workload scene_workload = [] {
    Workload w;
    const sim::scene::Scene scene =
        sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/aliasing_ladder.yaml");
    const sim::world::World world = sim::world::generate_world(scene);
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

double median_of(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The bare loop: same mesh batches and textures, a shader that only samples the texture,
// colour (RGBA8) and window depth (32F) attachments, both read back. Its own context.
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

class BareRenderer {
 public:
  explicit BareRenderer(const Workload& work) : k_(CameraIntrinsics::kinect_v1()) {
    context_.make_current();
    const sim::render::ProceduralTextures generator(work.seed, sim::scene::AppearanceThemes{});
    std::map<sim::render::TextureKey, sim::render::TextureImage> images;
    for (const sim::world::Triangle& t : work.mesh.triangles) {
      if (!images.contains(sim::render::texture_key_of(t)))
        images.emplace(sim::render::texture_key_of(t),
                       generator.make(sim::render::texture_key_of(t)));
    }
    for (const auto& [key, image] : images)
      textures_.emplace(key, std::make_unique<sim::render::GlTexture>(image));
    mesh_ = std::make_unique<sim::render::GlMesh>(sim::render::batch_mesh(
        work.mesh, [&](const sim::render::TextureKey& key) -> const sim::render::TextureImage& {
          return images.at(key);
        }));
    program_ = std::make_unique<sim::render::GlProgram>(kBareVertex, kBareFragment);
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glGenRenderbuffers(2, targets_);
    glBindRenderbuffer(GL_RENDERBUFFER, targets_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, k_.width_px, k_.height_px);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, targets_[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, targets_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, k_.width_px, k_.height_px);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, targets_[1]);
    glViewport(0, 0, k_.width_px, k_.height_px);
    glEnable(GL_DEPTH_TEST);
    program_->use();
    glUniform1i(program_->uniform("albedo"), 0);
    world_to_clip_location_ = program_->uniform("world_to_clip");
    color_.resize(4 * static_cast<std::size_t>(k_.width_px * k_.height_px));
    depth_.resize(static_cast<std::size_t>(k_.width_px * k_.height_px));
  }
  ~BareRenderer() {
    context_.make_current();
    glDeleteRenderbuffers(2, targets_);
    glDeleteFramebuffers(1, &framebuffer_);
  }

  void frame(const Pose& camera_to_world) {
    context_.make_current();
    const Eigen::Matrix4f world_to_clip =
        sim::render::RgbdRenderer::projection_matrix(k_, 0.05, 40.0) *
        camera_to_world.inverse().matrix().cast<float>();
    glUniformMatrix4fv(world_to_clip_location_, 1, GL_FALSE, world_to_clip.data());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mesh_->bind();
    for (const sim::render::MeshBatch& batch : mesh_->batches()) {
      textures_.at(batch.key)->bind();
      mesh_->draw(batch);
    }
    glReadPixels(0, 0, k_.width_px, k_.height_px, GL_BGRA, GL_UNSIGNED_BYTE, color_.data());
    glReadPixels(0, 0, k_.width_px, k_.height_px, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
    benchmark::DoNotOptimize(color_.data());
    benchmark::DoNotOptimize(depth_.data());
  }

 private:
  CameraIntrinsics k_;
  sim::render::OsmesaContext context_;
  std::map<sim::render::TextureKey, std::unique_ptr<sim::render::GlTexture>> textures_;
  std::unique_ptr<sim::render::GlMesh> mesh_;
  std::unique_ptr<sim::render::GlProgram> program_;
  unsigned framebuffer_ = 0, targets_[2] = {0, 0};
  GLint world_to_clip_location_ = -1;
  std::vector<unsigned char> color_;
  std::vector<float> depth_;
};

double ms_between(std::chrono::steady_clock::time_point a,
                  std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// What both harness benchmarks compare: the bare loop and the harness (renderer with the
// options WIFISLAM_BENCH_LIGHTS asks for, default depth sensor model) on one workload.
struct HarnessAndBare {
  explicit HarnessAndBare(int which)
      : work(workload(which)),
        bare(work),
        renderer(k, options_from_environment()),
        sensor(sim::scene::DepthSensorSpec{}, k, work.seed) {
    renderer.set_world(work.mesh, work.lights, work.seed, sim::scene::AppearanceThemes{});
  }
  static sim::render::RenderOptions options_from_environment() {
    sim::render::RenderOptions options;
    if (const char* lights = std::getenv("WIFISLAM_BENCH_LIGHTS"))
      options.max_lights = std::atoi(lights);
    return options;
  }
  const Pose& pose(std::int64_t frame) const {
    return work.poses[frame % static_cast<std::int64_t>(work.poses.size())];
  }

  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work;
  BareRenderer bare;
  sim::render::RgbdRenderer renderer;
  const sim::render::DepthSensorModel sensor;
  sim::render::RenderedView view;
  cv::Mat measured;
};

// Bare frame and harness frame of the same pose, alternately, so both see the same machine
// load (these machines are noisy); the ratio is of medians over the same stretch of time.
void BM_HarnessVsBare(benchmark::State& state) {
  HarnessAndBare h(static_cast<int>(state.range(0)));
  std::vector<double> bare_ms, render_ms, sensor_ms, frame_ms;
  std::int64_t frame = 0;
  for (auto _ : state) {
    const Pose& pose = h.pose(frame);
    const auto t0 = std::chrono::steady_clock::now();
    h.bare.frame(pose);
    const auto t1 = std::chrono::steady_clock::now();
    h.renderer.render(pose, h.view);
    const auto t2 = std::chrono::steady_clock::now();
    h.sensor.measure(h.view.depth_m, h.view.incidence_cos, frame, h.measured);
    const auto t3 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(h.measured.data);
    ++frame;
    bare_ms.push_back(ms_between(t0, t1));
    render_ms.push_back(ms_between(t1, t2));
    sensor_ms.push_back(ms_between(t2, t3));
    frame_ms.push_back(ms_between(t1, t3));
    state.SetIterationTime(ms_between(t1, t3) / 1000.0);
  }
  const double bare_median = median_of(bare_ms), frame_median = median_of(frame_ms);
  state.counters["bare_ms"] = bare_median;
  state.counters["render_ms"] = median_of(render_ms);
  state.counters["sensor_ms"] = median_of(sensor_ms);
  state.counters["frame_ms"] = frame_median;
  state.counters["frame_over_bare"] = frame_median / bare_median;
  state.counters["render_over_bare"] = median_of(render_ms) / bare_median;
}

// The render path as the generator runs it: frame k+1 is submitted before frame k's sensor model
// runs, so the model (and the unpack of the next frame's wait) overlaps llvmpipe's rasterizer
// threads. Stretches of kStretch consecutive poses, alternately bare, harness one frame after the
// other, and harness pipelined; each counter is a median over stretches of the time a frame.
// pipelined_over_bare is the throughput ratio a long run sees; serial_over_bare is
// BM_HarnessVsBare's frame_over_bare h.measured in stretches.
void BM_PipelinedVsBare(benchmark::State& state) {
  constexpr int kStretch = 8;
  HarnessAndBare h(static_cast<int>(state.range(0)));
  std::vector<double> bare_ms, serial_ms, pipelined_ms;
  std::int64_t first = 0;
  const auto pose_of = [&](std::int64_t frame) -> const Pose& { return h.pose(frame); };
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kStretch; ++i) h.bare.frame(pose_of(first + i));
    const auto t1 = std::chrono::steady_clock::now();
    for (int i = 0; i < kStretch; ++i) {
      h.renderer.render(pose_of(first + i), h.view);
      h.sensor.measure(h.view.depth_m, h.view.incidence_cos, first + i, h.measured);
      benchmark::DoNotOptimize(h.measured.data);
    }
    const auto t2 = std::chrono::steady_clock::now();
    h.renderer.submit(pose_of(first));
    for (int i = 0; i < kStretch; ++i) {
      h.renderer.collect(h.view);
      if (i + 1 < kStretch) h.renderer.submit(pose_of(first + i + 1));
      h.sensor.measure(h.view.depth_m, h.view.incidence_cos, first + i, h.measured);
      benchmark::DoNotOptimize(h.measured.data);
    }
    const auto t3 = std::chrono::steady_clock::now();
    first += kStretch;
    bare_ms.push_back(ms_between(t0, t1) / kStretch);
    serial_ms.push_back(ms_between(t1, t2) / kStretch);
    pipelined_ms.push_back(ms_between(t2, t3) / kStretch);
    state.SetIterationTime(ms_between(t2, t3) / 1000.0);
  }
  const double bare_median = median_of(bare_ms);
  state.counters["bare_ms"] = bare_median;
  state.counters["serial_ms"] = median_of(serial_ms);
  state.counters["pipelined_ms"] = median_of(pipelined_ms);
  state.counters["serial_over_bare"] = median_of(serial_ms) / bare_median;
  state.counters["pipelined_over_bare"] = median_of(pipelined_ms) / bare_median;
}

// The depth sensor model on one rendered view: Arg 0 the defaults, Arg 1 with lateral noise on.
void BM_SensorModelOnly(benchmark::State& state) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work = workload(0);
  sim::render::RgbdRenderer renderer(k);
  renderer.set_world(work.mesh, work.lights, work.seed, sim::scene::AppearanceThemes{});
  sim::scene::DepthSensorSpec spec;
  spec.lateral_noise = state.range(0) == 1;
  const sim::render::DepthSensorModel sensor(spec, k, work.seed);
  const sim::render::RenderedView view = renderer.render(work.poses[5]);
  cv::Mat measured;
  std::int64_t frame = 0;
  for (auto _ : state) {
    sensor.measure(view.depth_m, view.incidence_cos, frame++, measured);
    benchmark::DoNotOptimize(measured.data);
  }
}

// The colour sensor model on one rendered view: Arg 0 both parts off (a copy, what the pipeline
// did before), 1 noise, 2 auto-exposure, 3 both.
void BM_ColorSensorModelOnly(benchmark::State& state) {
  const CameraIntrinsics k = CameraIntrinsics::kinect_v1();
  const Workload& work = workload(0);
  sim::render::RgbdRenderer renderer(k);
  renderer.set_world(work.mesh, work.lights, work.seed, sim::scene::AppearanceThemes{});
  sim::scene::ColorSensorSpec spec;
  spec.noise = (state.range(0) & 1) != 0;
  spec.auto_exposure = (state.range(0) & 2) != 0;
  sim::render::ColorSensorModel sensor(spec, 30.0, work.seed);
  const sim::render::RenderedView view = renderer.render(work.poses[5]);
  cv::Mat measured;
  std::int64_t frame = 0;
  for (auto _ : state) {
    sensor.measure(view.color_bgr, frame++, measured);
    benchmark::DoNotOptimize(measured.data);
  }
}

// Both workloads, timed by the frames' own clocks, at least 4 s each.
void harness_args(benchmark::internal::Benchmark* b) {
  b->ArgName("corridor")
      ->Arg(0)
      ->Arg(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond)
      ->MinTime(4.0);
}
BENCHMARK(BM_HarnessVsBare)->Apply(harness_args);
BENCHMARK(BM_PipelinedVsBare)->Apply(harness_args);
BENCHMARK(BM_SensorModelOnly)->ArgName("lateral")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColorSensorModelOnly)
    ->ArgName("noise1_ae2")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace wifislam

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
