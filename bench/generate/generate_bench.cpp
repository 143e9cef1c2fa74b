// `wifislam generate scenes/c_hall.yaml` throughput and peak memory, with images (640x480) and
// with --no-images, at 1 000 and 10 000 frames (memory must stay flat as the run grows), and the
// share of time per stage. The baseline is the renderer alone on the same poses (render +
// readback, the raw cost the pipeline cannot avoid): `ratio_to_render` = pipeline time per frame
// / bare render time per frame.
//
// Peak memory is per benchmark: the kernel's high-water mark (VmHWM) is reset through
// /proc/self/clear_refs before each run.
//
//   build/<dir>/bench/generate/generate_bench [--benchmark_filter=...]
//   WIFISLAM_BENCH_DIR=/big/disk ...   (output folder; default the system temp folder)

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "sim/generate/dataset_writer.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"

namespace {

using namespace wifislam;
namespace fs = std::filesystem;

void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
    std::getline(status, key);
  }
  return 0.0;
}

fs::path bench_folder() {
  const char* dir = std::getenv("WIFISLAM_BENCH_DIR");
  return fs::path(dir ? dir : fs::temp_directory_path().string()) / "wifislam_generate_bench";
}

const sim::scene::Scene& c_hall() {
  static const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml");
  return scene;
}

void BM_Generate(benchmark::State& state) {
  const std::int64_t frames = state.range(0);
  const bool images = state.range(1) != 0;
  sim::generate::GenerateOptions options;
  options.max_frames = frames;
  options.camera = images ? sim::generate::CameraOutput::kColourAndDepth
                          : sim::generate::CameraOutput::kNoImages;
  options.overwrite = true;
  sim::generate::GenerateSummary summary;
  for (auto _ : state) {
    reset_peak_memory();
    summary = sim::generate::generate_dataset(c_hall(), bench_folder(), options);
    state.SetIterationTime(summary.total_s);
  }
  const double peak_mb = peak_memory_mb();
  fs::remove_all(bench_folder());
  const double total = summary.total_s;
  state.counters["fps"] = summary.frames_per_second();
  state.counters["peak_MB"] = peak_mb;
  state.counters["dataset_MB"] = summary.bytes_written / 1e6;
  state.counters["setup_s"] = summary.world_s;
  state.counters["share_render"] = summary.render_s / total;
  state.counters["share_sensor"] = summary.sensor_s / total;
  state.counters["share_radio"] = summary.radio_s / total;
  // Encoding and I/O run on worker threads: shares of thread time, they overlap the render.
  state.counters["share_png"] = summary.png_encode_s / total;
  state.counters["share_io"] = summary.io_s / total;
  state.counters["threads"] = summary.threads;
  if (images && summary.frames > 0) {
    // Baseline: the renderer alone on the first 200 frame poses.
    sim::generate::GenerateOptions bare_options = options;
    bare_options.max_frames = std::min<std::int64_t>(frames, 200);
    sim::generate::GenerationPipeline pipeline(c_hall(), bare_options);
    sim::render::RgbdRenderer& renderer = *pipeline.renderer();
    sim::render::RenderedView view;
    std::int64_t n = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::int64_t k = 0; k < pipeline.schedule().frame_count(); ++k, ++n) {
      const Timestamp t = pipeline.schedule().frame_time(k);
      renderer.render(pipeline.mount().camera_to_world(pipeline.motion().state_at(t)), view);
    }
    const double bare_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.counters["bare_render_ms"] = 1e3 * bare_s / n;
    state.counters["ratio_to_render"] = (total - summary.world_s) / summary.frames / (bare_s / n);
  }
}

BENCHMARK(BM_Generate)
    ->ArgNames({"frames", "images"})
    ->Args({1000, 1})
    ->Args({10000, 1})
    ->Args({1000, 0})
    ->Args({10000, 0})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
