#include "eval/loop_closure_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::eval {

namespace {

double rotation_deg(const Eigen::Matrix3d& r) {
  return Eigen::AngleAxisd(r).angle() * 180.0 / std::numbers::pi;
}

struct Partner {
  std::int64_t keyframe = -1;
  double path_m = 0.0;
};

}  // namespace

LoopClosureScore score_loop_closures(const std::vector<KeyframeTruth>& keyframes,
                                     const std::vector<DetectedLoopClosure>& detected,
                                     const std::string& loop_closures_file,
                                     const DepthLookup& depth, const CameraIntrinsics& intrinsics,
                                     const EvalOptions& options) {
  LoopClosureScore score;
  const auto n = static_cast<std::int64_t>(keyframes.size());
  auto overlap_of = [&](std::int64_t a, std::int64_t b) {
    const KeyframeTruth& ka = keyframes[static_cast<std::size_t>(a)];
    const KeyframeTruth& kb = keyframes[static_cast<std::size_t>(b)];
    ViewOverlap o =
        view_overlap(ka.ground_truth, nullptr, kb.ground_truth, nullptr, intrinsics, options);
    if (!o.within_geometric_bound) return o;
    const DepthView* da = depth(ka.time);
    const DepthView* db = da ? depth(kb.time) : nullptr;
    ++score.pairs_tested;
    if (!da || !db) {
      ++score.pairs_geometric_only;
      return o;
    }
    return view_overlap(ka.ground_truth, da, kb.ground_truth, db, intrinsics, options);
  };

  // True revisits: for each later keyframe j, any earlier i far enough along the path whose view
  // overlaps; the nearest candidates are tried first (most likely to overlap).
  std::vector<Partner> partner(keyframes.size());
  std::vector<std::pair<double, std::int64_t>> candidates;
  for (std::int64_t j = 0; j < n; ++j) {
    const KeyframeTruth& kj = keyframes[static_cast<std::size_t>(j)];
    candidates.clear();
    for (std::int64_t i = 0; i < j; ++i) {
      const KeyframeTruth& ki = keyframes[static_cast<std::size_t>(i)];
      if (kj.path_m - ki.path_m < options.revisit_min_path_m) continue;
      const double d = (kj.ground_truth.translation() - ki.ground_truth.translation()).norm();
      if (d <= options.overlap_max_distance_m) candidates.emplace_back(d, i);
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [d, i] : candidates) {
      if (overlap_of(i, j).overlap) {
        partner[static_cast<std::size_t>(j)] = {
            i, kj.path_m - keyframes[static_cast<std::size_t>(i)].path_m};
        ++score.revisit_keyframes;
        break;
      }
    }
  }

  // Episodes: runs of revisiting keyframes with small gaps.
  std::int64_t last = -1;
  for (std::int64_t j = 0; j < n; ++j) {
    const Partner& p = partner[static_cast<std::size_t>(j)];
    if (p.keyframe < 0) continue;
    if (last >= 0 && j - last - 1 <= options.episode_max_gap_keyframes) {
      score.episodes.back().last_keyframe = j;
      ++score.episodes.back().revisiting_keyframes;
    } else {
      score.episodes.push_back({j, j, 1, p.keyframe, p.path_m, false});
    }
    last = j;
  }

  // Detected loop closures.
  for (const DetectedLoopClosure& lc : detected) {
    for (std::int64_t id : {lc.from_keyframe, lc.to_keyframe}) {
      if (id >= n) {
        throw ParseError(fmt::format("{}:{}", loop_closures_file, lc.line),
                         id == lc.from_keyframe ? "from_keyframe" : "to_keyframe",
                         fmt::format("keyframe {} is not in keyframes.txt ({} keyframes)", id, n));
      }
    }
    ScoredLoopClosure s;
    s.detected = lc;
    const KeyframeTruth& from = keyframes[static_cast<std::size_t>(lc.from_keyframe)];
    const KeyframeTruth& to = keyframes[static_cast<std::size_t>(lc.to_keyframe)];
    s.path_between_m = std::abs(to.path_m - from.path_m);
    s.overlap = overlap_of(lc.from_keyframe, lc.to_keyframe);
    const Pose gt_from_to = from.ground_truth.inverse() * to.ground_truth;
    const Pose error = gt_from_to.inverse() * lc.from_to;
    s.translation_error_m = error.translation().norm();
    s.rotation_error_deg = rotation_deg(error.linear());
    const bool pose_ok = s.translation_error_m <= options.loop_max_translation_error_m &&
                         s.rotation_error_deg <= options.loop_max_rotation_error_deg;
    s.correct = s.overlap.overlap && pose_ok;
    if (s.correct) {
      s.verdict = "correct";
    } else if (!s.overlap.within_geometric_bound) {
      s.verdict = "views do not overlap (outside geometric bound)";
    } else if (!s.overlap.overlap) {
      s.verdict = "views do not overlap (depth)";
    } else {
      s.verdict = "relative pose off";
    }
    ++score.detected;
    if (s.correct) {
      ++score.correct;
      for (std::size_t e = 0; e < score.episodes.size(); ++e) {
        RevisitEpisode& ep = score.episodes[e];
        const bool touches =
            (lc.from_keyframe >= ep.first_keyframe && lc.from_keyframe <= ep.last_keyframe) ||
            (lc.to_keyframe >= ep.first_keyframe && lc.to_keyframe <= ep.last_keyframe);
        if (touches) {
          ep.detected = true;
          if (s.episode < 0) s.episode = static_cast<int>(e);
        }
      }
    } else {
      ++score.false_positives;
    }
    score.closures.push_back(std::move(s));
  }
  for (const RevisitEpisode& ep : score.episodes) score.false_negatives += ep.detected ? 0 : 1;
  score.false_positive_pct = score.detected ? 100.0 * static_cast<double>(score.false_positives) /
                                                  static_cast<double>(score.detected)
                                            : 0.0;
  score.false_negative_pct = score.episodes.empty()
                                 ? 0.0
                                 : 100.0 * static_cast<double>(score.false_negatives) /
                                       static_cast<double>(score.episodes.size());
  return score;
}

nlohmann::ordered_json to_json(const ScoredLoopClosure& s) {
  const DetectedLoopClosure& d = s.detected;
  nlohmann::ordered_json j;
  j["from_keyframe"] = d.from_keyframe;
  j["to_keyframe"] = d.to_keyframe;
  j["from_time"] = d.from_time.to_string(6);
  j["to_time"] = d.to_time.to_string(6);
  j["role"] = d.role;
  j["inliers"] = d.inliers;
  j["correct"] = s.correct;
  j["verdict"] = s.verdict;
  j["gt_distance_m"] = s.overlap.distance_m;
  j["gt_view_angle_deg"] = s.overlap.angle_deg;
  j["gt_path_between_m"] = s.path_between_m;
  j["overlap_depth_checked"] = s.overlap.depth_checked;
  j["overlap_fraction"] = s.overlap.fraction;
  j["translation_error_m"] = s.translation_error_m;
  j["rotation_error_deg"] = s.rotation_error_deg;
  j["episode"] = s.episode;
  return j;
}

nlohmann::ordered_json to_json(const RevisitEpisode& e) {
  return {{"first_keyframe", e.first_keyframe},
          {"last_keyframe", e.last_keyframe},
          {"revisiting_keyframes", e.revisiting_keyframes},
          {"first_partner", e.first_partner},
          {"first_partner_path_m", e.first_partner_path_m},
          {"detected", e.detected}};
}

}  // namespace wifislam::eval
