#include "eval/loop_closure_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/run_format.hpp"

namespace wifislam::eval {

namespace {

double rotation_deg(const Eigen::Matrix3d& r) {
  return Eigen::AngleAxisd(r).angle() * 180.0 / std::numbers::pi;
}

struct Partner {
  std::int64_t keyframe = -1;
  double path_m = 0.0;
};

/// Scores one run's accepted edges against its keyframes' ground truth, in four steps: the true
/// revisits (view overlap), their episodes, each edge's verdict, and the counts.
class ClosureScorer {
 public:
  ClosureScorer(const std::vector<KeyframeTruth>& keyframes, const DepthLookup& depth,
                const CameraIntrinsics& intrinsics, const EvalOptions& options)
      : keyframes_(keyframes),
        depth_(depth),
        intrinsics_(intrinsics),
        options_(options),
        n_(static_cast<std::int64_t>(keyframes.size())) {}

  LoopClosureScore score(const std::vector<AcceptedEdge>& edges) {
    const std::vector<Partner> partner = find_revisits();
    group_episodes(partner);
    for (const AcceptedEdge& edge : edges) score_edge(edge);
    count_false_negatives();
    return std::move(score_);
  }

 private:
  const KeyframeTruth& keyframe(std::int64_t k) const {
    return keyframes_[static_cast<std::size_t>(k)];
  }

  /// Whether two keyframes' views overlap: the geometric bound, then the depth test where both
  /// depth images exist.
  ViewOverlap overlap_of(std::int64_t a, std::int64_t b) {
    const KeyframeTruth& ka = keyframe(a);
    const KeyframeTruth& kb = keyframe(b);
    ViewOverlap o =
        view_overlap(ka.ground_truth, nullptr, kb.ground_truth, nullptr, intrinsics_, options_);
    if (!o.within_geometric_bound) return o;
    const DepthView* da = depth_(ka.time);
    const DepthView* db = da ? depth_(kb.time) : nullptr;
    ++score_.pairs_tested;
    if (!da || !db) {
      ++score_.pairs_geometric_only;
      return o;
    }
    return view_overlap(ka.ground_truth, da, kb.ground_truth, db, intrinsics_, options_);
  }

  /// True revisits: for each later keyframe j, any earlier i far enough along the path whose view
  /// overlaps; the nearest candidates are tried first (most likely to overlap).
  std::vector<Partner> find_revisits() {
    std::vector<Partner> partner(keyframes_.size());
    std::vector<std::pair<double, std::int64_t>> candidates;
    for (std::int64_t j = 0; j < n_; ++j) {
      const KeyframeTruth& kj = keyframe(j);
      candidates.clear();
      for (std::int64_t i = 0; i < j; ++i) {
        const KeyframeTruth& ki = keyframe(i);
        if (kj.path_m - ki.path_m < options_.revisit_min_path_m) continue;
        const double d = (kj.ground_truth.translation() - ki.ground_truth.translation()).norm();
        if (d <= options_.overlap_max_distance_m) candidates.emplace_back(d, i);
      }
      std::sort(candidates.begin(), candidates.end());
      for (const auto& [d, i] : candidates) {
        if (overlap_of(i, j).overlap) {
          partner[static_cast<std::size_t>(j)] = {i, kj.path_m - keyframe(i).path_m};
          ++score_.revisit_keyframes;
          break;
        }
      }
    }
    return partner;
  }

  /// Episodes: runs of revisiting keyframes with small gaps.
  void group_episodes(const std::vector<Partner>& partner) {
    std::int64_t last = -1;
    for (std::int64_t j = 0; j < n_; ++j) {
      const Partner& p = partner[static_cast<std::size_t>(j)];
      if (p.keyframe < 0) continue;
      if (last >= 0 && j - last - 1 <= options_.episode_max_gap_keyframes) {
        score_.episodes.back().last_keyframe = j;
        ++score_.episodes.back().revisiting_keyframes;
      } else {
        score_.episodes.push_back({j, j, 1, p.keyframe, p.path_m, false, false});
      }
      last = j;
    }
  }

  /// An accepted edge: the visual and loop ones far enough apart along the path are scored.
  void score_edge(const AcceptedEdge& edge) {
    for (const auto& [id, key] : {std::pair{edge.from_keyframe, &edge.from_key},
                                  std::pair{edge.to_keyframe, &edge.to_key}}) {
      if (id < 0 || id >= n_) {
        throw ParseError(edge.where, *key,
                         fmt::format("keyframe {} is not in keyframes.txt ({} keyframes)", id, n_));
      }
    }
    if (edge.type != run_folder::edge_type::kVisual && edge.type != run_folder::edge_type::kLoop) {
      return;
    }
    ++score_.edges_considered;
    const KeyframeTruth& from = keyframe(edge.from_keyframe);
    const KeyframeTruth& to = keyframe(edge.to_keyframe);
    ScoredLoopClosure s;
    s.path_between_m = std::abs(to.path_m - from.path_m);
    if (s.path_between_m < options_.revisit_min_path_m) {
      ++score_.edges_short_path;  // tracking and local edges, not loop closures
      return;
    }
    s.edge = edge;
    s.true_distance_m = (to.ground_truth.translation() - from.ground_truth.translation()).norm();
    s.overlap = overlap_of(edge.from_keyframe, edge.to_keyframe);
    const Pose gt_from_to = from.ground_truth.inverse() * to.ground_truth;
    const Pose error = gt_from_to.inverse() * edge.from_to;
    s.translation_error_m = error.translation().norm();
    s.rotation_error_deg = rotation_deg(error.linear());
    s.verdict = classify_loop_closure(s.translation_error_m, s.rotation_error_deg,
                                      s.true_distance_m, options_);
    s.far = is_far_wrong_place(s.verdict, s.true_distance_m, options_);
    count_verdict(s, edge);
    if (s.correct()) mark_detected_episodes(s, edge);
    score_.closures.push_back(std::move(s));
  }

  void count_verdict(const ScoredLoopClosure& s, const AcceptedEdge& edge) {
    for (LoopClosureCounts* counts : {&score_.online, &score_.after_pruning}) {
      if (counts == &score_.after_pruning && edge.pruned) continue;
      ++counts->scored;
      switch (s.verdict) {
        case LoopClosureVerdict::kCorrect:
          ++counts->correct;
          break;
        case LoopClosureVerdict::kRightPlaceImprecise:
          ++counts->right_place_imprecise;
          break;
        case LoopClosureVerdict::kWrongPlace:
          ++counts->wrong_place;
          break;
      }
      if (s.far) ++counts->far_wrong_place;
    }
  }

  /// A correct edge detects every episode it touches (after pruning, if it survived).
  void mark_detected_episodes(ScoredLoopClosure& s, const AcceptedEdge& edge) {
    for (std::size_t e = 0; e < score_.episodes.size(); ++e) {
      RevisitEpisode& ep = score_.episodes[e];
      const bool touches =
          (edge.from_keyframe >= ep.first_keyframe && edge.from_keyframe <= ep.last_keyframe) ||
          (edge.to_keyframe >= ep.first_keyframe && edge.to_keyframe <= ep.last_keyframe);
      if (!touches) continue;
      ep.detected_online = true;
      if (!edge.pruned) ep.detected_after_pruning = true;
      if (s.episode < 0) s.episode = static_cast<int>(e);
    }
  }

  void count_false_negatives() {
    auto percent = [](std::int64_t part, std::int64_t whole) {
      return whole ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
    };
    const auto episodes = static_cast<std::int64_t>(score_.episodes.size());
    for (const RevisitEpisode& ep : score_.episodes) {
      score_.online.false_negatives += ep.detected_online ? 0 : 1;
      score_.after_pruning.false_negatives += ep.detected_after_pruning ? 0 : 1;
    }
    for (LoopClosureCounts* counts : {&score_.online, &score_.after_pruning}) {
      counts->false_positive_pct = percent(counts->wrong_place, counts->scored);
      counts->false_negative_pct = percent(counts->false_negatives, episodes);
    }
  }

  const std::vector<KeyframeTruth>& keyframes_;
  const DepthLookup& depth_;
  const CameraIntrinsics& intrinsics_;
  const EvalOptions& options_;
  const std::int64_t n_;
  LoopClosureScore score_;
};

}  // namespace

LoopClosureScore score_loop_closures(const std::vector<KeyframeTruth>& keyframes,
                                     const std::vector<AcceptedEdge>& edges,
                                     const DepthLookup& depth, const CameraIntrinsics& intrinsics,
                                     const EvalOptions& options) {
  return ClosureScorer(keyframes, depth, intrinsics, options).score(edges);
}

nlohmann::ordered_json LoopClosureCounts::to_json() const {
  return {{"scored", scored},
          {"correct", correct},
          {"right_place_imprecise", right_place_imprecise},
          {"wrong_place", wrong_place},
          {"far_wrong_place", far_wrong_place},
          {"false_positive_pct", false_positive_pct},
          {"false_negatives", false_negatives},
          {"false_negative_pct", false_negative_pct}};
}

nlohmann::ordered_json to_json(const ScoredLoopClosure& s,
                               const std::vector<KeyframeTruth>& keyframes) {
  const AcceptedEdge& e = s.edge;
  nlohmann::ordered_json j;
  j["from_keyframe"] = e.from_keyframe;
  j["to_keyframe"] = e.to_keyframe;
  j["from_time"] = keyframes[static_cast<std::size_t>(e.from_keyframe)].time.to_string(6);
  j["to_time"] = keyframes[static_cast<std::size_t>(e.to_keyframe)].time.to_string(6);
  j["type"] = e.type;
  j["role"] = e.role;
  j["inliers"] = e.inliers;
  j["pruned"] = e.pruned;
  j["weight"] = e.weight;
  j["verdict"] = to_string(s.verdict);
  j["far"] = s.far;
  j["translation_error_m"] = s.translation_error_m;
  j["rotation_error_deg"] = s.rotation_error_deg;
  j["gt_distance_m"] = s.true_distance_m;
  j["gt_path_between_m"] = s.path_between_m;
  j["gt_view_angle_deg"] = s.overlap.angle_deg;
  j["overlap"] = s.overlap.overlap;
  j["overlap_depth_checked"] = s.overlap.depth_checked;
  j["overlap_fraction"] = s.overlap.fraction;
  j["episode"] = s.episode;
  return j;
}

nlohmann::ordered_json to_json(const RevisitEpisode& e) {
  return {{"first_keyframe", e.first_keyframe},
          {"last_keyframe", e.last_keyframe},
          {"revisiting_keyframes", e.revisiting_keyframes},
          {"first_partner", e.first_partner},
          {"first_partner_path_m", e.first_partner_path_m},
          {"detected_online", e.detected_online},
          {"detected_after_pruning", e.detected_after_pruning}};
}

}  // namespace wifislam::eval
