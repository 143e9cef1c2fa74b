#include "slam/frontend/rtabmap/rtabmap_front_end.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <deque>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/run_format.hpp"
#include "slam/frontend/rtabmap/likelihood.hpp"
#include "slam/frontend/rtabmap/rtabmap_memory_csv.hpp"

namespace wifislam::slam::frontend::rtabmap {

namespace {

/// CPU time of the calling thread (ms): unaffected by other processes competing for the cores.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

}  // namespace

namespace {

/// Nodes as RTAB-Map makes them: Rtabmap/DetectionRate, RGBD/LinearUpdate, RGBD/AngularUpdate.
FrontEndSchedule rtabmap_schedule(const RtabmapOptions& options) {
  FrontEndSchedule schedule;
  schedule.keyframes =
      KeyframeSchedule{options.detection_rate_hz > 0 ? 1.0 / options.detection_rate_hz : 0.0,
                       options.linear_update_m, options.angular_update_rad};
  return schedule;
}

}  // namespace

RtabmapFrontEnd::RtabmapFrontEnd(const RtabmapOptions& options,
                                 const optimize::PoseGraphOptions& graph_options)
    : FrontEnd("rtabmap",
               std::make_unique<AcceptGraphConsistentHypotheses>(
                   std::make_unique<AcceptBestLoopHypothesis>(), options.optimize_max_error,
                   graph_options, graph_options.incremental_max_iterations),
               rtabmap_schedule(options)),
      options_(options),
      vocabulary_(options.nndr_ratio),
      memory_(options.stm_size),
      filter_(rtabmap::parse_prediction_lc("bayes_prediction_lc", options.prediction_lc),
              options.virtual_place_prior) {}

bool RtabmapFrontEnd::searchable(graph::KeyframeId keyframe) const {
  const rtabmap::MemoryPlace place = memory_.place(keyframe);
  return place == rtabmap::MemoryPlace::kStm || place == rtabmap::MemoryPlace::kWm;
}

void RtabmapFrontEnd::retrieve(graph::KeyframeId node, RtabmapNodeRecord& record) {
  memory_.retrieve(node);
  vocabulary_.enable_references(node, words_of_.at(node));
  ++record.entered_wm;
}

std::map<rtabmap::NodeId, int> RtabmapFrontEnd::neighbours_in_memory(graph::KeyframeId node,
                                                                     int max_margin,
                                                                     bool include_ltm) const {
  std::map<rtabmap::NodeId, int> margin{{node, 0}};
  if (graph_ == nullptr) return margin;
  std::deque<graph::KeyframeId> queue{node};
  while (!queue.empty()) {
    const graph::KeyframeId current = queue.front();
    queue.pop_front();
    const int m = margin.at(current);
    if (m >= max_margin) continue;
    for (graph::KeyframeId next : graph_->adjacent(current)) {
      if (margin.contains(next)) continue;
      const rtabmap::MemoryPlace place = memory_.place(next);
      if (place == rtabmap::MemoryPlace::kUnknown) continue;
      if (!include_ltm && place == rtabmap::MemoryPlace::kLtm) continue;
      margin[next] = m + 1;
      queue.push_back(next);
    }
  }
  return margin;
}

bool RtabmapFrontEnd::linked_to_stm(graph::KeyframeId node) const {
  if (graph_ == nullptr) return false;
  for (graph::KeyframeId k : graph_->adjacent(node)) {
    if (memory_.place(k) == rtabmap::MemoryPlace::kStm) return true;
  }
  return false;
}

std::vector<Candidate> RtabmapFrontEnd::select(const SelectionQuery& query) {
  start_node(query);
  const graph::KeyframeId t = query.keyframe;
  add_to_memory(query);
  rehearse(t);
  pending_.memory_update_cpu_ms = phase_cpu_ms();
  retrieve_around_last_best();
  retrieve_similar_wifi_clusters();
  phase_cpu_ms();  // retrieval is RTAB-Map's own timing category, in no phase here
  const HypothesisScores scores = update_hypotheses(t);
  return candidates_of(query, scores);
}

void RtabmapFrontEnd::start_node(const SelectionQuery& query) {
  started_ = std::chrono::steady_clock::now();
  started_cpu_ms_ = thread_cpu_ms();
  phase_started_cpu_ms_ = started_cpu_ms_;
  graph_ = query.graph;
  pending_ = RtabmapNodeRecord{};
  pending_.node = query.keyframe;
  immune_now_.clear();
  last_transferred_.clear();
}

double RtabmapFrontEnd::phase_cpu_ms() {
  const double now = thread_cpu_ms();
  const double elapsed = now - phase_started_cpu_ms_;
  phase_started_cpu_ms_ = now;
  return elapsed;
}

void RtabmapFrontEnd::add_to_memory(const SelectionQuery& query) {
  const graph::KeyframeId t = query.keyframe;
  cv::Mat descriptors;
  if (query.features != nullptr) {
    descriptors = rtabmap::strongest_descriptors(
        query.features->keypoints, query.features->descriptors, options_.max_features);
  }
  const std::int64_t comparisons_before = vocabulary_.distance_computations();
  words_of_[t] = vocabulary_.add_node(t, descriptors);
  pending_.word_comparisons = vocabulary_.distance_computations() - comparisons_before;
  if (memory_.add(t) >= 0) ++pending_.entered_wm;
  pending_.words = vocabulary_.dictionary_size();
}

void RtabmapFrontEnd::rehearse(graph::KeyframeId t) {
  if (t >= 1 && memory_.place(t - 1) == rtabmap::MemoryPlace::kStm &&
      rtabmap::node_similarity(words_of_.at(t - 1), words_of_.at(t)) >=
          options_.rehearsal_similarity) {
    memory_.merge(t - 1, t);
    pending_.rehearsed = true;
  }
}

void RtabmapFrontEnd::retrieve_around_last_best() {
  if (last_best_ < 0) return;
  std::map<int, std::vector<graph::KeyframeId>> by_margin;
  for (const auto& [id, m] : neighbours_in_memory(last_best_, filter_.max_margin(), true)) {
    if (memory_.place(id) != rtabmap::MemoryPlace::kStm) by_margin[m].push_back(id);
  }
  for (auto& [m, ids] : by_margin) {
    for (auto it = ids.rbegin(); it != ids.rend(); ++it) {
      immune_now_.insert(*it);
      if (memory_.place(*it) == rtabmap::MemoryPlace::kLtm &&
          pending_.retrieved < options_.max_retrieved) {
        retrieve(*it, pending_);
        ++pending_.retrieved;
      }
    }
  }
}

void RtabmapFrontEnd::retrieve_similar_wifi_clusters() {
  wifi_immune_ = wifi_immune_nodes();
  for (graph::KeyframeId k : wifi_immune_) {
    if (options_.wifi_max_retrieved > 0 && pending_.wifi_retrieved >= options_.wifi_max_retrieved)
      break;
    if (memory_.place(k) == rtabmap::MemoryPlace::kLtm) {
      retrieve(k, pending_);
      ++pending_.wifi_retrieved;
    }
  }
}

RtabmapFrontEnd::HypothesisScores RtabmapFrontEnd::update_hypotheses(graph::KeyframeId t) {
  std::vector<graph::KeyframeId> scored(memory_.wm().begin(), memory_.wm().end());
  if (wifi() != nullptr) scored = wifi()->bound(scored);
  pending_.scored = scored.size();
  rtabmap::RawLikelihood raw = rtabmap::tf_idf_likelihood(words_of_.at(t), scored, vocabulary_,
                                                          words_of_, memory_.in_memory());
  pending_.likelihood_terms = raw.terms;
  HypothesisScores scores;
  if (!scored.empty()) {
    const rtabmap::NormalisedLikelihood l = rtabmap::normalise_likelihood(raw.score);
    scores.likelihood = l.node;
    pending_.likelihood_cpu_ms = phase_cpu_ms();
    // The prediction's neighbourhoods: WM nodes within the margin in the graph.
    filter_.update(l.node, l.virtual_place, [this](rtabmap::NodeId id, int max_margin) {
      std::map<rtabmap::NodeId, int> out;
      for (const auto& [k, m] : neighbours_in_memory(id, max_margin, false)) {
        if (memory_.place(k) == rtabmap::MemoryPlace::kWm) out[k] = m;
      }
      return out;
    });
    scores.best = filter_.best();
    pending_.virtual_probability = filter_.virtual_probability();
    pending_.hypotheses = filter_.posterior().size();
    pending_.posterior_cpu_ms = phase_cpu_ms();
  } else {
    pending_.likelihood_cpu_ms = phase_cpu_ms();
  }
  pending_.best = scores.best.first;
  pending_.best_probability = scores.best.second;
  last_best_ = scores.best.first;
  return scores;
}

std::vector<Candidate> RtabmapFrontEnd::candidates_of(const SelectionQuery& query,
                                                      const HypothesisScores& scores) {
  const graph::KeyframeId t = query.keyframe;
  const auto& best = scores.best;
  std::vector<Candidate> out;
  const auto compared = [&](graph::KeyframeId k) {
    return std::find(query.already_compared.begin(), query.already_compared.end(), k) !=
           query.already_compared.end();
  };
  if (t >= 1 && !compared(t - 1)) out.push_back({t - 1, CandidateRole::kPredecessor});
  if (best.first >= 0 && best.second >= options_.loop_threshold) {
    pending_.loop_candidate = best.first;
    if (!compared(best.first) && best.first != t - 1) {
      out.push_back({best.first, CandidateRole::kLongTerm});
    }
  }
  if (options_.proximity_by_space) {
    for (graph::KeyframeId k : proximity_candidates(t, scores.likelihood)) {
      const bool listed =
          std::any_of(out.begin(), out.end(), [&](const Candidate& c) { return c.keyframe == k; });
      if (listed || compared(k)) continue;
      out.push_back({k, CandidateRole::kProximity});
      ++pending_.proximity_candidates;
    }
  }
  return out;
}

std::vector<graph::KeyframeId> RtabmapFrontEnd::proximity_candidates(
    graph::KeyframeId t, const std::map<rtabmap::NodeId, double>& likelihood) {
  if (graph_ == nullptr || options_.local_radius_m <= 0) return {};
  const Pose& here = graph_->node(t).pose;
  const Eigen::Vector3d heading = here.linear().col(2);  // camera optical axis
  const double cos_max_angle = std::cos(options_.proximity_angle_deg * M_PI / 180.0);
  const auto distance_m = [&](graph::KeyframeId k) {
    return (graph_->node(k).pose.translation() - here.translation()).norm();
  };
  const auto looks_alike_way = [&](graph::KeyframeId k) {
    return graph_->node(k).pose.linear().col(2).dot(heading) >= cos_max_angle;
  };

  // WM nodes near the estimated position, within the graph depth (ascending ids).
  std::vector<graph::KeyframeId> nearest;
  const auto consider = [&](graph::KeyframeId k) {
    if (k != t && memory_.place(k) == rtabmap::MemoryPlace::kWm &&
        distance_m(k) <= options_.local_radius_m) {
      nearest.push_back(k);
    }
  };
  if (options_.proximity_max_graph_depth > 0) {
    for (const auto& [k, margin] :
         neighbours_in_memory(t, options_.proximity_max_graph_depth, false)) {
      consider(k);
    }
  } else {
    for (graph::KeyframeId k : memory_.wm()) consider(k);
    std::sort(nearest.begin(), nearest.end());
  }
  if (wifi() != nullptr) nearest = wifi()->bound(nearest);

  // Paths: runs of consecutive ids, ordered by their highest likelihood, then the newer first
  // (RTAB-Map walks its map of (likelihood, id) keys backwards).
  struct Path {
    std::vector<graph::KeyframeId> nodes;
    graph::KeyframeId most_likely = -1;
    double highest_likelihood = 0.0;
  };
  std::vector<Path> paths;
  for (graph::KeyframeId k : nearest) {
    if (paths.empty() || k != paths.back().nodes.back() + 1) paths.emplace_back();
    Path& path = paths.back();
    path.nodes.push_back(k);
    const auto it = likelihood.find(k);
    const double v = it == likelihood.end() ? 0.0 : it->second;
    if (v > path.highest_likelihood) {
      path.highest_likelihood = v;
      path.most_likely = k;
    }
  }
  std::sort(paths.begin(), paths.end(), [](const Path& a, const Path& b) {
    if (a.highest_likelihood != b.highest_likelihood) {
      return a.highest_likelihood > b.highest_likelihood;
    }
    return a.nodes.front() > b.nodes.front();
  });

  std::vector<graph::KeyframeId> out;
  for (const Path& path : paths) {
    // RGBD/ProximityMaxPaths 0: no limit, as in RTAB-Map.
    if (options_.proximity_max_paths > 0 &&
        static_cast<int>(out.size()) >= options_.proximity_max_paths) {
      break;
    }
    graph::KeyframeId chosen = -1;
    if (path.most_likely >= 0 && looks_alike_way(path.most_likely)) {
      chosen = path.most_likely;
    } else {
      double nearest_m = std::numeric_limits<double>::infinity();
      for (graph::KeyframeId k : path.nodes) {
        if (looks_alike_way(k) && distance_m(k) < nearest_m) {
          nearest_m = distance_m(k);
          chosen = k;
        }
      }
    }
    if (chosen < 0 || graph_->has_edge(chosen, t)) continue;
    if (options_.proximity_filtering_radius_m > 0 &&
        distance_m(chosen) >= options_.proximity_filtering_radius_m) {
      continue;
    }
    out.push_back(chosen);
  }
  return out;
}

std::vector<graph::KeyframeId> RtabmapFrontEnd::wifi_immune_nodes() const {
  std::vector<graph::KeyframeId> out;
  if (wifi() == nullptr) return out;
  const auto cap = static_cast<std::size_t>(std::max(0, options_.wifi_max_immune));
  // Most similar cluster first; within a cluster the newest nodes first, since transfers take
  // the oldest first and a cap should keep what the unbounded rule would keep longest.
  for (const wifi::SimilarCluster& similar : wifi()->similar_clusters()) {
    const wifi::WifiCluster& cluster = wifi()->clusters().clusters().at(similar.cluster);
    for (auto it = cluster.keyframes.rbegin(); it != cluster.keyframes.rend(); ++it) {
      if (cap > 0 && out.size() >= cap) return out;
      const rtabmap::MemoryPlace place = memory_.place(*it);
      if (place == rtabmap::MemoryPlace::kWm || place == rtabmap::MemoryPlace::kLtm) {
        out.push_back(*it);
      }
    }
  }
  return out;
}

double RtabmapFrontEnd::node_time_ms(const RtabmapNodeRecord& record) const {
  return options_.time_source == RtabmapTimeSource::kWall ? record.wall_ms : record.cost_ms;
}

void RtabmapFrontEnd::after_verification(const VerificationReport& report) {
  RtabmapNodeRecord& r = pending_;
  if (report.keyframe != r.node) {
    throw std::logic_error(fmt::format("rtabmap: keyframe {} verified, but node {} was selected",
                                       report.keyframe, r.node));
  }
  r.verifications = static_cast<int>(report.comparisons.size());
  for (const ComparisonOutcome& c : report.comparisons) {
    if (c.candidate.keyframe == r.loop_candidate && c.candidate.role == CandidateRole::kLongTerm) {
      r.loop_verified = c.verified;
      r.loop_accepted = c.accepted;
      ++r.loop_verifications;
    }
  }
  const RtabmapCostModel& cost = options_.cost;
  r.loop_closure_cost_ms = cost.ms_per_likelihood_term * static_cast<double>(r.likelihood_terms) +
                           cost.ms_per_scored_node * static_cast<double>(r.scored) +
                           cost.ms_per_hypothesis * static_cast<double>(r.hypotheses) +
                           cost.ms_per_verification * r.loop_verifications;
  r.cost_ms =
      cost.ms_per_node + cost.ms_per_word_comparison * static_cast<double>(r.word_comparisons) +
      r.loop_closure_cost_ms + cost.ms_per_verification * (r.verifications - r.loop_verifications);

  // 6. Memory management under Rtabmap/TimeThr (Memory::forget: one more than entered WM).
  const std::set<graph::KeyframeId> wifi_immune(wifi_immune_.begin(), wifi_immune_.end());
  r.immune = static_cast<int>(std::count_if(
      wifi_immune.begin(), wifi_immune.end(),
      [&](graph::KeyframeId k) { return memory_.place(k) == rtabmap::MemoryPlace::kWm; }));
  const auto kept = [&](graph::KeyframeId id) {
    return immune_now_.contains(id) || id == r.best || linked_to_stm(id) ||
           wifi_immune.contains(id);
  };
  r.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_)
                  .count();
  r.cpu_ms = thread_cpu_ms() - started_cpu_ms_;
  const double time_ms = node_time_ms(r);
  if (time_ms > options_.time_threshold_ms) {
    r.over_budget_ms = time_ms - options_.time_threshold_ms;
    last_transferred_ = memory_.transfer(static_cast<std::size_t>(r.entered_wm) + 1, kept);
    for (graph::KeyframeId id : last_transferred_) {
      vocabulary_.disable_references(id, words_of_.at(id));
    }
    r.transferred = static_cast<int>(last_transferred_.size());
  }
  r.stm = memory_.stm().size();
  r.wm = memory_.wm().size();
  r.ltm = memory_.ltm().size();
  records_.push_back(r);
}

void RtabmapFrontEnd::write_own_outputs(const std::filesystem::path& run_dir) const {
  namespace col = rtabmap_memory_csv::column;
  std::string csv = run_folder::csv_header(col::kAll);
  for (const RtabmapNodeRecord& r : records_) {
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},", r.node, r.stm, r.wm, r.ltm,
                       r.entered_wm, r.retrieved, r.wifi_retrieved, r.transferred, r.immune,
                       r.rehearsed ? 1 : 0, r.words, r.word_comparisons, r.scored,
                       r.likelihood_terms, r.hypotheses);
    csv += fmt::format("{},{:.6g},{:.6g},{},{},{},{},{},{},", r.best, r.best_probability,
                       r.virtual_probability, r.loop_candidate, r.loop_verified ? 1 : 0,
                       r.loop_accepted ? 1 : 0, r.verifications, r.loop_verifications,
                       r.proximity_candidates);
    csv += fmt::format("{:.4f},{:.4f},{:.4f},{:.4f},", r.memory_update_cpu_ms, r.likelihood_cpu_ms,
                       r.posterior_cpu_ms, r.loop_closure_cost_ms);
    csv += fmt::format("{:.4f},{:.4f},{:.4f},{:.4f}\n", r.cost_ms, r.wall_ms, r.cpu_ms,
                       r.over_budget_ms);
  }
  write_file_atomic(run_dir / rtabmap_memory_csv::kFileName, csv);
}

nlohmann::json RtabmapFrontEnd::own_summary() const {
  std::int64_t transferred = 0, retrieved = 0, wifi_retrieved = 0, rehearsed = 0, over = 0,
               candidates = 0, accepted = 0, proximity = 0;
  std::size_t max_wm = 0;
  double wm_sum = 0.0, over_ms = 0.0, cost_ms = 0.0, wall_ms = 0.0, cpu_ms = 0.0;
  double loop_closure_cost_ms = 0.0, likelihood_posterior_cpu_ms = 0.0, memory_update_cpu_ms = 0.0;
  for (const RtabmapNodeRecord& r : records_) {
    loop_closure_cost_ms += r.loop_closure_cost_ms;
    likelihood_posterior_cpu_ms += r.likelihood_cpu_ms + r.posterior_cpu_ms;
    memory_update_cpu_ms += r.memory_update_cpu_ms;
    cost_ms += r.cost_ms;
    wall_ms += r.wall_ms;
    cpu_ms += r.cpu_ms;
    transferred += r.transferred;
    retrieved += r.retrieved;
    wifi_retrieved += r.wifi_retrieved;
    rehearsed += r.rehearsed ? 1 : 0;
    over += r.over_budget_ms > 0 ? 1 : 0;
    over_ms += r.over_budget_ms;
    candidates += r.loop_candidate >= 0 ? 1 : 0;
    accepted += r.loop_accepted ? 1 : 0;
    proximity += r.proximity_candidates;
    max_wm = std::max(max_wm, r.wm);
    wm_sum += static_cast<double>(r.wm);
  }
  const auto json_ms = [](double v) -> nlohmann::json {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json("inf");
  };
  return {
      {"nodes", records_.size()},
      {"stm_size", options_.stm_size},
      {"time_threshold_ms", json_ms(options_.time_threshold_ms)},
      {"time_source", to_string(options_.time_source)},
      {"memory",
       {{"stm", memory_.stm().size()},
        {"wm", memory_.wm().size()},
        {"ltm", memory_.ltm().size()},
        {"max_wm", max_wm},
        {"mean_wm", records_.empty() ? 0.0 : wm_sum / static_cast<double>(records_.size())},
        {"transferred", transferred},
        {"retrieved", retrieved},
        {"wifi_retrieved", wifi_retrieved},
        {"rehearsed", rehearsed}}},
      {"vocabulary_words", vocabulary_.size()},
      {"nodes_over_budget", over},
      {"proximity_candidates", proximity},
      // Sum over nodes of what TimeThr is compared with, under each time source.
      {"node_time_s", {{"cost", cost_ms * 1e-3}, {"wall", wall_ms * 1e-3}, {"cpu", cpu_ms * 1e-3}}},
      // RTAB-Map's loop-closure detection (likelihood, posterior, the loop hypothesis'
      // verification): its cost-model share, and the measured CPU time of its first two parts
      // (the verification's measured time is timing.json's role long_term).
      {"loop_closure_time_s",
       {{"cost", loop_closure_cost_ms * 1e-3},
        {"likelihood_posterior_cpu", likelihood_posterior_cpu_ms * 1e-3}}},
      {"memory_update_cpu_s", memory_update_cpu_ms * 1e-3},
      {"over_budget_ms", over_ms},
      {"loop_candidates", candidates},
      {"loop_closures_accepted", accepted}};
}

}  // namespace wifislam::slam::frontend::rtabmap
