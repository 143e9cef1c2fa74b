#include "slam/bow/keyframe_database.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace wifislam::slam::bow {

void KeyframeDatabase::add(graph::KeyframeId keyframe, const BowVector& vector) {
  if (!vectors_.emplace(keyframe, vector).second) {
    throw std::logic_error("KeyframeDatabase: keyframe added twice");
  }
  for (const auto& [word, weight] : vector) {
    std::vector<graph::KeyframeId>& list = inverted_[word];
    list.insert(std::lower_bound(list.begin(), list.end(), keyframe), keyframe);
  }
}

void KeyframeDatabase::erase(graph::KeyframeId keyframe) {
  const auto it = vectors_.find(keyframe);
  if (it == vectors_.end()) return;
  for (const auto& [word, weight] : it->second) {
    std::vector<graph::KeyframeId>& list = inverted_[word];
    list.erase(std::lower_bound(list.begin(), list.end(), keyframe));
    if (list.empty()) inverted_.erase(word);
  }
  vectors_.erase(it);
}

std::vector<graph::KeyframeId> KeyframeDatabase::keyframes_with(WordId word) const {
  const auto it = inverted_.find(word);
  return it == inverted_.end() ? std::vector<graph::KeyframeId>{} : it->second;
}

std::vector<LoopCandidate> KeyframeDatabase::loop_candidates(
    const BowVector& query, const std::vector<graph::KeyframeId>& connected, double min_score,
    const NeighbourFunction& neighbours) const {
  return bow::loop_candidates({this}, query, connected, min_score, neighbours,
                              &last_postings_read_);
}

std::vector<LoopCandidate> loop_candidates(const std::vector<const KeyframeDatabase*>& databases,
                                           const BowVector& query,
                                           const std::vector<graph::KeyframeId>& connected,
                                           double min_score, const NeighbourFunction& neighbours,
                                           std::size_t* postings_read) {
  std::size_t read = 0;
  const std::set<graph::KeyframeId> excluded(connected.begin(), connected.end());
  // 1. Keyframes sharing words with the query, and how many (and which database holds each).
  std::map<graph::KeyframeId, int> shared_words;
  std::map<graph::KeyframeId, const KeyframeDatabase*> holder;
  for (const KeyframeDatabase* database : databases) {
    for (const auto& [word, weight] : query) {
      const auto it = database->inverted_.find(word);
      if (it == database->inverted_.end()) continue;
      read += it->second.size();
      for (graph::KeyframeId k : it->second) {
        if (excluded.count(k)) continue;
        ++shared_words[k];
        holder[k] = database;
      }
    }
  }
  if (postings_read != nullptr) *postings_read = read;
  if (shared_words.empty()) return {};

  // 2. Scores of those sharing more than 0.8 x the most shared words.
  int most = 0;
  for (const auto& [k, n] : shared_words) most = std::max(most, n);
  const double min_common = 0.8 * most;
  std::map<graph::KeyframeId, double>
      scored;  // every keyframe over min_common (ORB-SLAM2's mLoopScore)
  std::vector<std::pair<graph::KeyframeId, double>> retained;
  for (const auto& [k, n] : shared_words) {
    if (n <= min_common) continue;
    const double s = l1_score(query, holder.at(k)->vectors_.at(k));
    scored[k] = s;
    if (s >= min_score) retained.emplace_back(k, s);
  }
  if (retained.empty()) return {};

  // 3. Groups: each retained keyframe with its scored covisible neighbours.
  std::vector<LoopCandidate> groups;
  double best_accumulated = 0.0;
  for (const auto& [k, s] : retained) {
    LoopCandidate group{k, s, s};
    for (graph::KeyframeId n : neighbours(k)) {
      const auto it = scored.find(n);
      if (it == scored.end()) continue;
      group.accumulated_score += it->second;
      if (it->second > group.score) {
        group.keyframe = n;
        group.score = it->second;
      }
    }
    best_accumulated = std::max(best_accumulated, group.accumulated_score);
    groups.push_back(group);
  }

  // 4. Groups over 0.75 x the best accumulated score, each representative once.
  std::sort(groups.begin(), groups.end(), [](const LoopCandidate& a, const LoopCandidate& b) {
    if (a.accumulated_score != b.accumulated_score)
      return a.accumulated_score > b.accumulated_score;
    return a.keyframe < b.keyframe;
  });
  std::vector<LoopCandidate> out;
  std::set<graph::KeyframeId> added;
  for (const LoopCandidate& g : groups) {
    if (g.accumulated_score > 0.75 * best_accumulated && added.insert(g.keyframe).second)
      out.push_back(g);
  }
  return out;
}

}  // namespace wifislam::slam::bow
