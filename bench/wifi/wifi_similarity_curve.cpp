// Signature similarity against distance, per scene (the paper's "Wi-Fi Similarity" figure): for
// every pair of pauses of the robot's route, the cosine similarity of their signatures (as the
// SLAM's Wi-Fi module forms them) against the ground-truth distance between them. Prints, per
// 2 m distance bin, the 10th/50th/90th percentile, and the share of pairs at or above the
// default `wifi_similarity` for near (< 4 m) and far (>= 12 m) pairs. Also times the vectorised
// similarity of one signature against many clusters.
//
//   wifi_similarity_curve [scene.yaml ...]     (default: every shipped scene)

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "core/tum_trajectory.hpp"
#include "core/wifi_csv.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"
#include "slam/wifi/signature_similarity.hpp"

namespace {

using namespace wifislam;
using namespace wifislam::slam;

struct PauseSample {
  Eigen::Vector3d position_m;
  wifi::WifiSignature signature;
};

std::vector<PauseSample> pause_samples(const sim::scene::Scene& scene,
                                       const std::filesystem::path& tmp) {
  sim::generate::GenerateOptions options;
  options.camera = sim::generate::CameraOutput::kNoImages;
  options.overwrite = true;
  sim::generate::generate_dataset(scene, tmp, options);
  const std::vector<WifiScan> scans = read_wifi_csv((tmp / "wifi.csv").string());
  const Trajectory truth = read_tum_trajectory((tmp / "groundtruth.txt").string());
  std::vector<PauseSample> out;
  wifi::PauseSignatureTracker tracker(wifi::WifiOptions{});
  int pause = 0;
  for (const WifiScan& scan : scans) {
    tracker.observe_scan(scan);
    // Where the robot stood: the ground-truth pose at (or just before) the scan's end.
    const auto it =
        std::upper_bound(truth.begin(), truth.end(), scan.end_time.ns,
                         [](std::int64_t t, const StampedPose& p) { return t < p.time.ns; });
    const Eigen::Vector3d position = (it == truth.begin() ? *it : *(it - 1)).translation_m;
    if (tracker.pause_count() != pause) {
      pause = tracker.pause_count();
      out.push_back({position, *tracker.current()});
    } else {
      out.back().signature = *tracker.current();
    }
  }
  return out;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5)];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> scenes;
  for (int i = 1; i < argc; ++i) scenes.emplace_back(argv[i]);
  if (scenes.empty()) {
    for (const char* name : {"c_hall", "b_hall", "j_hall", "a_hall", "aliasing_ladder"}) {
      scenes.push_back(std::filesystem::path(WIFISLAM_SCENES_DIR) / (std::string(name) + ".yaml"));
    }
  }
  const wifi::WifiOptions defaults;
  const auto tmp = std::filesystem::temp_directory_path() / "wifislam_similarity_curve";
  for (const auto& path : scenes) {
    const sim::scene::Scene scene = sim::scene::load_scene_file(path.string());
    const std::vector<PauseSample> pauses = pause_samples(scene, tmp);
    std::map<int, std::vector<double>> bins;
    int near = 0, near_similar = 0, far = 0, far_similar = 0;
    for (std::size_t i = 0; i < pauses.size(); ++i) {
      for (std::size_t j = i + 1; j < pauses.size(); ++j) {
        const double d = (pauses[i].position_m - pauses[j].position_m).norm();
        const double s =
            wifi::cosine_similarity(pauses[i].signature, pauses[j].signature, defaults.floor_dbm);
        bins[std::min(15, static_cast<int>(d / 2.0))].push_back(s);
        const bool similar = s >= defaults.similarity;
        if (d < 4.0) near += 1, near_similar += similar;
        if (d >= 12.0) far += 1, far_similar += similar;
      }
    }
    fmt::print("{}: {} pauses\n  distance m   pairs   p10    p50    p90\n", scene.name,
               pauses.size());
    for (const auto& [bin, values] : bins) {
      fmt::print("  {:>2}-{:<2}{}  {:>6}  {:.3f}  {:.3f}  {:.3f}\n", 2 * bin, 2 * bin + 2,
                 bin == 15 ? "+" : " ", values.size(), percentile(values, 0.1),
                 percentile(values, 0.5), percentile(values, 0.9));
    }
    fmt::print(
        "  similarity >= {:.2f}: {:.0f} % of pairs < 4 m apart, {:.0f} % of pairs >= 12 m\n\n",
        defaults.similarity, near ? 100.0 * near_similar / near : 0.0,
        far ? 100.0 * far_similar / far : 0.0);
  }
  std::filesystem::remove_all(tmp);

  // Clustering cost: one query against N representatives of 70 APs (j_hall's count).
  for (int clusters : {10, 100, 1000}) {
    wifi::SignatureSimilarityIndex index(defaults.floor_dbm);
    std::vector<wifi::ApStrength> s;
    for (int ap = 0; ap < 70; ++ap)
      s.push_back({static_cast<wifi::AccessPointKey>(ap * 16), -60.0 - ap % 30});
    const wifi::WifiSignature signature(s);
    for (int c = 0; c < clusters; ++c) index.add(signature);
    const int repeats = 2000;
    double sum = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r) sum += index.similarities(signature)(0);
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count() /
        repeats;
    fmt::print("similarity of one signature against {:>4} clusters: {:8.2f} us (check {:.0f})\n",
               clusters, us, sum / repeats);
  }
  return 0;
}
