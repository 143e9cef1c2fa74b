// rgbdslam on the c_hall scene, frames streamed from the generator (640x480). For every frame the
// bare cost of OpenCV's ORB (detect + compute, same settings) is measured in the same run, so the
// figure that matters is the ratio pipeline / bare ORB, which survives noisy machines
// (docs/benchmarks.md). Rendering is not counted: the pipeline's own clock is.
//
// Environment: WIFISLAM_BENCH_SCENE (default c_hall), WIFISLAM_BENCH_FPS (default 30),
// WIFISLAM_BENCH_MAX_FRAMES (default 900; -1 = the whole route), WIFISLAM_BENCH_SET
// (comma-separated key=value SLAM options).
//
// Also: frame-to-frame descriptor matching against OpenCV's BFMatcher on the same descriptors.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/generate/generator_stream.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/match/descriptor_matcher.hpp"
#include "slam/system/slam_system.hpp"

namespace {

using namespace wifislam;

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? std::string(v) : fallback;
}

void BM_RgbdslamVersusBareOrb(benchmark::State& state) {
  const std::string scene_name = env_or("WIFISLAM_BENCH_SCENE", "c_hall");
  const double fps = std::stod(env_or("WIFISLAM_BENCH_FPS", "30"));
  const std::int64_t max_frames = std::stoll(env_or("WIFISLAM_BENCH_MAX_FRAMES", "900"));
  slam::SlamOptions options;
  std::stringstream settings(env_or("WIFISLAM_BENCH_SET", ""));
  for (std::string item; std::getline(settings, item, ',');) {
    if (!item.empty()) slam::set_option_assignment(options, item);
  }
  const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/" + scene_name + ".yaml");

  for (auto _ : state) {
    sim::generate::GenerateOptions generate;
    generate.fps = fps;
    generate.max_frames = max_frames;
    sim::generate::GeneratorStream stream(scene, generate);
    slam::system::SlamSystem system(options, {stream.intrinsics(), stream.camera_in_base(),
                                              stream.has_wifi(), stream.has_odometry()});
    const cv::Ptr<cv::ORB> orb = cv::ORB::create(
        options.features.max_keypoints, static_cast<float>(options.features.scale_factor),
        options.features.pyramid_levels, 31, 0, 2, cv::ORB::HARRIS_SCORE, 31,
        options.features.fast_threshold);
    double bare_orb_s = 0.0;
    std::int64_t frames = 0;
    while (std::optional<SensorEvent> event = stream.next()) {
      if (const auto* frame = std::get_if<RgbdFrame>(&*event)) {
        const auto start = std::chrono::steady_clock::now();
        cv::Mat grey;
        cv::cvtColor(frame->rgb, grey, cv::COLOR_BGR2GRAY);
        std::vector<cv::KeyPoint> keypoints;
        cv::Mat descriptors;
        orb->detectAndCompute(grey, cv::noArray(), keypoints, descriptors);
        bare_orb_s +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++frames;
      }
      system.process(*event);
    }
    system.finish();
    const slam::util::Instrumentation& inst = system.instrumentation();
    const double pipeline_s = inst.seconds(slam::module::kTotal);
    state.counters["frames"] = static_cast<double>(frames);
    state.counters["keyframes"] = static_cast<double>(system.graph().node_count());
    state.counters["loop_closures"] = static_cast<double>(system.loop_closures().size());
    state.counters["pipeline_fps"] = frames / pipeline_s;
    state.counters["bare_orb_fps"] = frames / bare_orb_s;
    state.counters["pipeline_over_bare_orb"] = pipeline_s / bare_orb_s;

    std::printf("\n%s at %.0f fps, %lld frames: pipeline %.1f fps, bare ORB %.1f fps, ratio %.2f\n",
                scene_name.c_str(), fps, static_cast<long long>(frames), frames / pipeline_s,
                frames / bare_orb_s, pipeline_s / bare_orb_s);
    std::printf("time per module (share of pipeline):\n");
    for (const auto& [name, m] : inst.modules()) {
      std::printf("  %-24s %8.3f s  %5.1f %%  (%lld calls)\n", name.c_str(), m.total_s,
                  100.0 * m.total_s / pipeline_s, static_cast<long long>(m.calls));
    }
    for (const auto& [name, value] : inst.counters()) {
      std::printf("  %-24s %lld\n", name.c_str(), static_cast<long long>(value));
    }
    // Loop-closure detection per keyframe against map size, in five bands of map size.
    const auto& searches = inst.keyframe_searches();
    if (!searches.empty()) {
      std::printf("loop-closure detection per keyframe vs map size:\n");
      const std::size_t bands = 5;
      for (std::size_t b = 0; b < bands; ++b) {
        const std::size_t lo = b * searches.size() / bands, hi = (b + 1) * searches.size() / bands;
        if (hi <= lo) continue;
        double seconds = 0.0, comparisons = 0.0;
        for (std::size_t i = lo; i < hi; ++i) {
          seconds += searches[i].seconds;
          comparisons += static_cast<double>(searches[i].comparisons);
        }
        const double n = static_cast<double>(hi - lo);
        std::printf("  map %5lld-%5lld keyframes: %7.2f ms/keyframe, %5.2f comparisons/keyframe\n",
                    static_cast<long long>(searches[lo].map_keyframes),
                    static_cast<long long>(searches[hi - 1].map_keyframes), 1000.0 * seconds / n,
                    comparisons / n);
      }
    }
  }
}
BENCHMARK(BM_RgbdslamVersusBareOrb)->Iterations(1)->Unit(benchmark::kSecond);

/// Frame-to-frame matching (slam/match's match_descriptors) against OpenCV's BFMatcher knnMatch
/// (k = 2), which it replaced with the same matches, on the ORB features of two c_hall frames 0.5 m
/// apart (one second of walking): the two alternate, and the ratio of their median times is the
/// figure.
void BM_MatchDescriptorsVersusBfMatcher(benchmark::State& state) {
  const sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml");
  sim::generate::GenerateOptions generate;
  generate.fps = 1;
  generate.max_frames = 15;  // the robot waits 10 s, then walks at 0.5 m/s
  sim::generate::GeneratorStream stream(scene, generate);
  const slam::SlamOptions options;
  const slam::feature::OrbFeatureExtractor extractor(options.features, stream.intrinsics());
  std::vector<slam::feature::FrameFeatures> frames;
  while (std::optional<SensorEvent> event = stream.next()) {
    if (const auto* frame = std::get_if<RgbdFrame>(&*event))
      frames.push_back(extractor.extract(*frame));
  }
  const slam::feature::FrameFeatures& query = frames[frames.size() - 2];
  const slam::feature::FrameFeatures& train = frames.back();
  cv::Mat train_with_depth;
  for (std::size_t i = 0; i < train.size(); ++i) {
    if (train.has_depth[i]) train_with_depth.push_back(train.descriptors.row(static_cast<int>(i)));
  }
  const auto seconds_of = [](const auto& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<double> ours_s, opencv_s;
  std::size_t matches = 0;
  for (auto _ : state) {
    for (int round = 0; round < 51; ++round) {
      ours_s.push_back(seconds_of([&] {
        matches = slam::match::match_descriptors(query, train, options.transform.matching).size();
      }));
      opencv_s.push_back(seconds_of([&] {
        std::vector<std::vector<cv::DMatch>> knn;
        cv::BFMatcher(cv::NORM_HAMMING, false)
            .knnMatch(query.descriptors, train_with_depth, knn, 2);
        benchmark::DoNotOptimize(knn.data());
      }));
    }
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double ours = median(ours_s), opencv = median(opencv_s);
  state.counters["ours_ms"] = 1000.0 * ours;
  state.counters["bfmatcher_ms"] = 1000.0 * opencv;
  state.counters["ours_over_bfmatcher"] = ours / opencv;
  std::printf(
      "\nmatch_descriptors, %zu x %d descriptors (%zu matches): %.3f ms, BFMatcher knnMatch "
      "%.3f ms, ratio %.2f (medians of %zu)\n",
      query.size(), train_with_depth.rows, matches, 1000.0 * ours, 1000.0 * opencv, ours / opencv,
      ours_s.size());
}
BENCHMARK(BM_MatchDescriptorsVersusBfMatcher)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
