#pragma once
// `wifislam study place`: greedy access-point placement. Starting from no access point, add the
// candidate position that best tells places along the route apart, one at a time, up to a
// budget; next to it, the same numbers of access points drawn at random from the same candidates.
//
// Candidates: free-space spots in rooms, corridors and halls, 0.4 m off the walls, no two closer
// than `candidate_spacing_m` (sim/site/ap_placement.hpp), at the scene's access_points.height_m
// and tx_power_dbm.
//
// Evaluation, at radio level (radio_resolution.hpp): the scene is simulated once with an access
// point at every candidate (placement explicit), so each candidate's readings at each pause are
// drawn once; a placement's pause signatures are those readings restricted to its access points.
// In this radio model an access point's readings are independent of which other access points
// exist (nothing models channel contention), so the restriction has the distribution of a scene
// with only those access points; it is not that scene's draws bit for bit (the per-scan noise
// stream and the shadowing streams are keyed by scan time and AP id, not by position). It makes
// every placement see the same draws, so greedy and random differ by where the access points
// stand, not by luck of the draws.
// Objective, lexicographic: the placement error (1 - near_similar_share) + far_similar_share,
// smaller is better; then the signature resolution (smaller is better; absent counts as
// infinitely coarse); then the candidate's index (the lattice order, so ties are deterministic).
// The error is what the Wi-Fi bounding of loop-closure search depends on: pause pairs under 4 m
// apart (the same place, a visual revisit) must be similar, or bounding drops true closures, and
// pairs over 12 m apart must not, or it lets far look-alikes through. Resolution alone is not the
// objective because it rewards signatures so fine that the same place is missed: on the J-hall
// twin a greedy search on resolution reached 0.5 m with only 44 % of the pairs under 4 m similar.
//
// Random baseline: for each count k, `random_draws` placements of k candidates drawn uniformly
// without replacement (stream "study/place/random/<k>/<draw>" of `seed`); the medians are reported.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "study/radio_resolution.hpp"

namespace wifislam::study {

struct PlacementOptions {
  int budget = 10;                   // access points to place
  double candidate_spacing_m = 3.0;  // finer: more candidates, slower, little gain below ~2 m
  int random_draws = 5;              // random placements per count
  std::uint64_t seed = 1;            // of the random baseline only
  slam::wifi::WifiOptions wifi;      // wifi_similarity and the RSSI floor, as the SLAM's
  std::function<void(const std::string&)> on_progress;
};

/// The most candidates a placement search takes; a larger plan needs a coarser spacing.
inline constexpr int kMaxPlacementCandidates = 3000;

struct PlacementStep {
  int count = 0;              // access points after this step
  int candidate = -1;         // index into PlacementResult::candidates
  RadioResolution greedy;     // with the chosen access points
  double greedy_error = 0.0;  // placement_error(greedy)
  double random_error = 0.0;  // medians over the random draws
  std::optional<double> random_resolution_m;
  double random_far_similar_share = 0.0;
  double random_near_similar_share = 0.0;
};

struct PlacementResult {
  std::vector<Eigen::Vector3d> candidates;
  std::vector<PlacementStep> steps;
  /// The scene's own access points, for reference.
  int scene_access_points = 0;
  RadioResolution scene_own;
  std::vector<Eigen::Vector2d> pause_positions_m;
  sim::world::FloorPlan plan;  // for drawing
  /// The level the candidates stand on, the route's (scene `levels:`; empty for one level).
  std::string level;
};

/// The chosen positions over the floor plan (candidates grey, pauses blue, access points numbered
/// in the order chosen), and the placement error and the resolution after each addition, greedy
/// against random; PNG and SVG of each into `folder`. Returns the files written.
std::vector<std::filesystem::path> plot_placement(const PlacementResult& result,
                                                  const std::string& scene_name,
                                                  const std::filesystem::path& folder);

/// Throws InvalidInputError when the route has fewer than two Wi-Fi pauses, or the budget exceeds
/// the candidates, or the plan has too many.
PlacementResult greedy_placement(const sim::scene::Scene& scene, const PlacementOptions& options);

/// (1 - near_similar_share) + far_similar_share: 0 when every pair under 4 m is similar and no
/// pair over 12 m is; 2 at worst.
double placement_error(const RadioResolution& r);
/// Objective order: true when `a` tells places apart better than `b` (see above; no index
/// tie-break).
bool places_better(const RadioResolution& a, const RadioResolution& b);

}  // namespace wifislam::study
