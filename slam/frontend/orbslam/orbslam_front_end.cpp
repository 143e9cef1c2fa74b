#include "slam/frontend/orbslam/orbslam_front_end.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/run_format.hpp"
#include "slam/bow/shipped_vocabulary.hpp"
#include "slam/frontend/orbslam/orbslam_queries_csv.hpp"

namespace wifislam::slam::frontend::orbslam {

namespace {

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
      .count();
}

}  // namespace

OrbslamFrontEnd::OrbslamFrontEnd(const OrbslamOptions& options)
    : FrontEnd("orbslam", std::make_unique<AcceptBestLoopHypothesis>()),
      options_(options),
      vocabulary_(bow::load_vocabulary(options.vocabulary)),
      covisibility_(options.covisibility_min_weight),
      consistency_(options.loop_consistency),
      last_loop_(0) {
  // ORB-SLAM's direct index sits 4 levels above the leaves of its L = 6 tree, at level 2 (100
  // nodes of k = 10): features are matched within one of ~100 regions of descriptor space. We
  // keep the level, not the distance from the leaves, so a shallower tree matches as coarsely.
  direct_index_levels_up_ = std::max(1, vocabulary_->depth() - 2);
}

void OrbslamFrontEnd::on_wifi_attached() {
  // The paper's per-cluster dictionaries: a keyframe enters the index of the cluster cluster
  // management gives it.
  wifi()->subscribe([this](const wifi::ClusterEvent& event) {
    by_cluster_[event.cluster].add(event.keyframe, bow_.at(event.keyframe));
  });
}

std::vector<const bow::KeyframeDatabase*> OrbslamFrontEnd::databases_to_search() const {
  if (wifi() == nullptr) return {&all_};
  std::vector<const bow::KeyframeDatabase*> out;
  if (!wifi()->has_signature()) {
    // No Wi-Fi information: every index, as vanilla.
    for (const auto& [cluster, database] : by_cluster_) out.push_back(&database);
    return out;
  }
  for (const wifi::SimilarCluster& similar : wifi()->similar_clusters()) {
    const auto it = by_cluster_.find(similar.cluster);
    if (it != by_cluster_.end()) out.push_back(&it->second);
  }
  // Keyframes made before the first scan are in no cluster; Wi-Fi cannot rule them out.
  const auto unclustered = by_cluster_.find(-1);
  if (unclustered != by_cluster_.end()) out.push_back(&unclustered->second);
  return out;
}

std::vector<Candidate> OrbslamFrontEnd::select(const SelectionQuery& query) {
  const auto started = std::chrono::steady_clock::now();
  graph_ = query.graph;
  const graph::KeyframeId id = query.keyframe;
  OrbslamQueryRecord record;
  record.keyframe = id;

  // 1. BoW vector and direct index.
  const feature::FrameFeatures& features = *query.features;
  bow::BowKeyframe& keyframe = bow_keyframes_[id];
  keyframe.descriptors = bow::pack_descriptors(features.descriptors);
  keyframe.angles_deg.reserve(features.keypoints.size());
  for (const cv::KeyPoint& k : features.keypoints) keyframe.angles_deg.push_back(k.angle);
  bow_[id] =
      vocabulary_->transform(features.descriptors, &keyframe.direct_index, direct_index_levels_up_);
  double query_ms = elapsed_ms(started);

  // 2. Local mapping candidates.
  std::vector<Candidate> out;
  std::set<graph::KeyframeId> taken(query.already_compared.begin(), query.already_compared.end());
  taken.insert(id);
  std::vector<graph::KeyframeId> local;
  if (id >= 1) {
    const graph::KeyframeId previous = id - 1;
    local.push_back(previous);
    if (taken.insert(previous).second) out.push_back({previous, CandidateRole::kPredecessor});
    for (graph::KeyframeId k : covisibility_.best(previous, options_.local_keyframes)) {
      local.push_back(k);
      if (k < id && taken.insert(k).second) out.push_back({k, CandidateRole::kNeighbour});
    }
  }

  // 3. Loop detection.
  const auto detection_started = std::chrono::steady_clock::now();
  std::vector<graph::KeyframeId> connected = query.already_compared;
  connected.insert(connected.end(), local.begin(), local.end());
  std::sort(connected.begin(), connected.end());
  connected.erase(std::unique(connected.begin(), connected.end()), connected.end());
  for (const Candidate& c : detect_loop(query, connected, record)) {
    if (taken.insert(c.keyframe).second) out.push_back(c);
  }

  // 4. Vanilla: into the one index after its own query. Wi-Fi: after cluster management.
  if (wifi() == nullptr) all_.add(id, bow_.at(id));
  query_ms += elapsed_ms(detection_started);
  record.query_ms = query_ms;
  records_.push_back(record);
  return out;
}

std::vector<Candidate> OrbslamFrontEnd::detect_loop(const SelectionQuery& query,
                                                    const std::vector<graph::KeyframeId>& connected,
                                                    OrbslamQueryRecord& record) {
  const graph::KeyframeId id = query.keyframe;
  if (id < last_loop_ + options_.keyframes_between_loops || connected.empty()) return {};
  record.detection_ran = true;
  const bow::BowVector& current = bow_.at(id);

  double min_score = 1.0;
  for (graph::KeyframeId k : connected)
    min_score = std::min(min_score, bow::l1_score(current, bow_.at(k)));
  record.min_score = min_score;

  const std::vector<const bow::KeyframeDatabase*> databases = databases_to_search();
  record.databases_searched = static_cast<int>(databases.size());
  for (const bow::KeyframeDatabase* d : databases) record.keyframes_searched += d->size();
  const bow::NeighbourFunction neighbours = [this](graph::KeyframeId k) {
    return covisibility_.best(k, options_.covisibility_group_size);
  };
  // Not candidates: the connected keyframes, and every keyframe too recent to be a loop closure
  // by the pipeline's loop rule. In ORB-SLAM2 those share map points with the keyframe and are
  // among its connected keyframes; here a robot lingering in one hall would otherwise verify
  // keyframes a few metres back as "loop" candidates at every keyframe. Path grows with the id,
  // so they are the keyframes from the first non-loop one on.
  std::vector<graph::KeyframeId> excluded = connected;
  if (query.loop_rule != nullptr) {
    for (graph::KeyframeId k = id - 1; k >= 0 && !query.loop_rule->is_loop(k, id); --k) {
      excluded.push_back(k);
    }
  }
  const std::vector<bow::LoopCandidate> candidates = bow::loop_candidates(
      databases, current, excluded, min_score, neighbours, &record.postings_read);
  record.candidates = static_cast<int>(candidates.size());

  // Temporal consistency: each candidate with its covisible keyframes.
  std::vector<std::pair<graph::KeyframeId, std::set<graph::KeyframeId>>> groups;
  for (const bow::LoopCandidate& c : candidates) {
    std::set<graph::KeyframeId> group{c.keyframe};
    for (graph::KeyframeId k : covisibility_.connected(c.keyframe)) group.insert(k);
    groups.emplace_back(c.keyframe, std::move(group));
  }
  const std::vector<graph::KeyframeId> consistent = consistency_.update(groups);
  record.consistent = static_cast<int>(consistent.size());

  // The SearchByBoW gate, then verification by the pipeline.
  std::vector<Candidate> out;
  const bow::BowKeyframe& mine = bow_keyframes_.at(id);
  for (graph::KeyframeId k : consistent) {
    if (bow::count_bow_matches(mine, bow_keyframes_.at(k), {}) >= options_.bow_min_matches) {
      out.push_back({k, CandidateRole::kLongTerm});
    }
  }
  record.bow_passed = static_cast<int>(out.size());
  return out;
}

void OrbslamFrontEnd::after_verification(const VerificationReport& report) {
  const graph::KeyframeId id = report.keyframe;
  OrbslamQueryRecord& record = records_.back();
  // Covisibility: the keyframe's accepted visual and loop edges (the tracking edge among them).
  if (graph_ != nullptr) {
    for (auto it = graph_->edges().rbegin(); it != graph_->edges().rend(); ++it) {
      if (it->from != id && it->to != id) break;  // the keyframe's edges were added last
      if (it->type == graph::EdgeType::kVisual || it->type == graph::EdgeType::kLoop) {
        covisibility_.add(it->from, it->to, it->inliers);
      }
    }
  }
  for (const ComparisonOutcome& c : report.comparisons) {
    if (c.accepted && c.edge_type == graph::EdgeType::kLoop &&
        c.candidate.role == CandidateRole::kLongTerm) {
      last_loop_ = id;
      record.accepted_loop = c.candidate.keyframe;
    }
  }
  if (wifi() != nullptr) {
    record.cluster = wifi()->cluster_of(id);
    // Without a signature the keyframe joined no cluster: the index every query reads.
    if (record.cluster < 0) by_cluster_[-1].add(id, bow_.at(id));
  }
}

void OrbslamFrontEnd::write_own_outputs(const std::filesystem::path& run_dir) const {
  namespace col = orbslam_queries_csv::column;
  std::string csv = run_folder::csv_header(col::kAll);
  for (const OrbslamQueryRecord& r : records_) {
    csv += fmt::format("{},{},{},{},{},{:.6g},{},{},{},{},{},{:.4f}\n", r.keyframe,
                       r.detection_ran ? 1 : 0, r.databases_searched, r.keyframes_searched,
                       r.postings_read, r.min_score, r.candidates, r.consistent, r.bow_passed,
                       r.accepted_loop, r.cluster, r.query_ms);
  }
  write_file_atomic(run_dir / orbslam_queries_csv::kFileName, csv);
}

nlohmann::json OrbslamFrontEnd::own_summary() const {
  std::size_t detections = 0, postings = 0, searched = 0, verified = 0;
  double query_ms = 0.0;
  for (const OrbslamQueryRecord& r : records_) {
    query_ms += r.query_ms;
    if (!r.detection_ran) continue;
    ++detections;
    postings += r.postings_read;
    searched += r.keyframes_searched;
    verified += static_cast<std::size_t>(r.bow_passed);
  }
  nlohmann::json out = {
      {"vocabulary",
       options_.vocabulary.empty() ? bow::kShippedVocabularyName : options_.vocabulary},
      {"vocabulary_sha256", bow::vocabulary_checksum(options_.vocabulary)},
      {"vocabulary_words", vocabulary_->word_count()},
      {"local_keyframes", options_.local_keyframes},
      {"covisibility_min_weight", options_.covisibility_min_weight},
      {"covisibility_edges", covisibility_.edge_count()},
      {"loop_detections", detections},
      {"loop_candidates_verified", verified},
      {"mean_postings_read", detections ? static_cast<double>(postings) / detections : 0.0},
      {"mean_keyframes_searched", detections ? static_cast<double>(searched) / detections : 0.0},
      // LoopClosing's DetectLoop and SearchByBoW (orbslam_queries.csv's query_ms, summed): the
      // query part of ORB-SLAM's loop-closure time (the paper's table "Loop closure compute
      // time"); its Sim3 verifications are the pipeline's long_term role.
      {"loop_closure_time_s", {{"query", query_ms / 1000.0}}}};
  if (wifi() != nullptr) out["keyframe_databases"] = by_cluster_.size();
  return out;
}

}  // namespace wifislam::slam::frontend::orbslam
