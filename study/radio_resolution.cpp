#include "study/radio_resolution.hpp"

#include <algorithm>
#include <map>
#include <memory>

#include "core/median.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/site/site.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"
#include "slam/wifi/signature_similarity.hpp"
#include "slam/wifi/wifi_cluster_map.hpp"

namespace wifislam::study {

std::vector<PauseSample> simulate_pauses(std::shared_ptr<const sim::site::Site> site,
                                         const slam::wifi::WifiOptions& wifi,
                                         std::vector<slam::wifi::AccessPointKey>* ap_keys) {
  sim::generate::GenerateOptions options;
  options.camera =
      sim::generate::CameraOutput::kNoFrames;  // the pauses need odometry and scans only
  sim::generate::GenerationPipeline pipeline(std::move(site), options);
  if (ap_keys) {
    ap_keys->clear();
    for (const radio_model::AccessPoint& ap : pipeline.site().access_points())
      ap_keys->push_back(ap.base_mac().value);
  }
  slam::wifi::PauseSignatureTracker tracker(wifi);
  std::vector<PauseSample> out;
  int pause = 0;
  while (auto generated = pipeline.next()) {
    if (const auto* odometry = std::get_if<OdometryReading>(&generated->event)) {
      tracker.observe_odometry(*odometry);
      continue;
    }
    const auto* scan = std::get_if<WifiScan>(&generated->event);
    if (!scan) continue;
    tracker.observe_scan(*scan);
    const sim::robot::RobotState state =
        pipeline.motion().state_at(pipeline.route_time(scan->end_time));
    if (tracker.pause_count() != pause) {
      pause = tracker.pause_count();
      out.push_back({state.position_m, *tracker.current()});
    } else if (!out.empty()) {
      out.back() = {state.position_m, *tracker.current()};
    }
  }
  return out;
}

RadioResolution radio_resolution(const std::vector<PauseSample>& pauses,
                                 const slam::wifi::WifiOptions& wifi) {
  RadioResolution r;
  r.pauses = static_cast<int>(pauses.size());
  std::map<int, std::vector<double>> bins;  // 1 m bins of true distance
  int near = 0, near_similar = 0, far = 0, far_similar = 0;
  std::size_t heard = 0;
  for (std::size_t i = 0; i < pauses.size(); ++i) {
    heard += pauses[i].signature.size();
    for (std::size_t j = i + 1; j < pauses.size(); ++j) {
      const double d_m = (pauses[i].position_m - pauses[j].position_m).norm();
      const double s =
          slam::wifi::cosine_similarity(pauses[i].signature, pauses[j].signature, wifi.floor_dbm);
      const bool similar = s >= wifi.similarity;
      bins[static_cast<int>(d_m)].push_back(s);
      ++r.pairs;
      if (d_m < 4.0) near += 1, near_similar += similar;
      if (d_m > 12.0) far += 1, far_similar += similar;
    }
  }
  r.near_similar_share = near ? static_cast<double>(near_similar) / near : 0.0;
  r.far_similar_share = far ? static_cast<double>(far_similar) / far : 0.0;
  r.aps_heard_per_pause = pauses.empty() ? 0.0 : static_cast<double>(heard) / pauses.size();

  // Medians of the bins with enough pairs, nearest first.
  std::vector<std::pair<double, double>> medians;  // (bin centre, median)
  for (auto& [bin, values] : bins) {
    if (static_cast<int>(values.size()) < kMinPairsPerBin) continue;
    medians.emplace_back(bin + 0.5, median(values));
  }
  // The crossing after the last bin at or above the threshold: beyond it places stay apart.
  std::size_t last_above = medians.size();
  for (std::size_t i = 0; i < medians.size(); ++i)
    if (medians[i].second >= wifi.similarity) last_above = i;
  if (last_above + 1 < medians.size()) {
    const auto& [above_m, above] = medians[last_above];
    const auto& [below_m, below] = medians[last_above + 1];
    const double t = (above - wifi.similarity) / (above - below);
    r.resolution_m = above_m + t * (below_m - above_m);
  }

  slam::wifi::WifiClusterMap clusters(wifi.similarity, wifi.floor_dbm);
  for (std::size_t k = 0; k < pauses.size(); ++k) {
    auto signature = std::make_shared<const slam::wifi::WifiSignature>(pauses[k].signature);
    const auto similar = clusters.similar_clusters(*signature);
    std::vector<slam::graph::KeyframeId> connected;
    if (k > 0) connected.push_back(static_cast<slam::graph::KeyframeId>(k - 1));
    clusters.assign(static_cast<slam::graph::KeyframeId>(k), signature, similar, connected);
  }
  r.clusters = static_cast<int>(clusters.clusters().size());
  return r;
}

}  // namespace wifislam::study
