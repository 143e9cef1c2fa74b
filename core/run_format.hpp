#pragma once
// The SLAM run folder (docs/run_folder.md): the names `wifislam slam` writes (slam/io) and
// `wifislam eval` reads (eval/), in one place, like dataset_format.hpp for datasets.
//
//   trajectory.txt     every frame, TUM (timestamp tx ty tz qx qy qz qw), camera-to-map
//   keyframes.txt      the keyframes, TUM, same frame; line k = keyframe id k
//   graph.json         nodes (keyframe id, frame index, time, pose) and edges (type
//                      odometry / visual / loop / weak, relative pose, information, inliers,
//                      and from format 3: "pruned" true when the back end's final pruning removed
//                      the edge, "weight" < 1 when it discounted one it could not remove without
//                      disconnecting the graph). Every edge accepted online is listed.
//   loop_closures.csv  one row per loop-closure edge, with the candidate role that found it
//   wifi_clusters.csv  Wi-Fi runs only: one row per cluster (slam/wifi/wifi_cluster_map.hpp); its
//                      members are keyframe ids (lines of keyframes.txt)
//   (a front end's own files: rtabmap_memory.csv, slam/frontend/rtabmap/rtabmap_memory_csv.hpp;
//    orbslam_queries.csv, slam/frontend/orbslam/orbslam_queries_csv.hpp)
//   timing.json        {"modules": {name: {"total_s", "calls"}}, "counters": {name: n},
//                       "roles": {role: {"comparisons", "ransac_runs", "verified", "accepted",
//                       "time_s"}}, "keyframe_searches": [...], "wall_s"}
//   run.json           {"format", "format_version", "frontend", "wifi", "options", counts, ...}
//
// Whether a run used the Wi-Fi module is run.json's "wifi", never guessed from which files exist.

#include <array>
#include <cstddef>
#include <string>

namespace wifislam::run_folder {

inline constexpr const char* kFormatName = "wifislam-run";
/// 2: run.json names the front end and the Wi-Fi switch separately and timing.json has "roles".
/// 3: graph.json edges carry "pruned" and "weight"; run.json has "pruning" (one entry per stage:
///    threshold_chi2, pruned, discounted).
inline constexpr int kFormatVersion = 3;

inline constexpr const char* kTrajectory = "trajectory.txt";
inline constexpr const char* kKeyframes = "keyframes.txt";
inline constexpr const char* kGraph = "graph.json";
inline constexpr const char* kLoopClosures = "loop_closures.csv";
inline constexpr const char* kWifiClusters = "wifi_clusters.csv";
inline constexpr const char* kTiming = "timing.json";
inline constexpr const char* kRun = "run.json";

/// run.json's "frontend" of a run made by an external program (interop/external_system.hpp):
/// "external:<system name>". Such a run writes only the files its system declares.
inline constexpr const char* kExternalFrontendPrefix = "external:";

/// Keys of run.json that readers rely on.
namespace run_key {
inline constexpr const char* kFormat = "format";
inline constexpr const char* kFormatVersion = "format_version";
inline constexpr const char* kFrontend = "frontend";  // "rgbdslam", without a Wi-Fi suffix
inline constexpr const char* kPruning = "pruning";    // format 3: the after-run pruning stages
inline constexpr const char* kWifi = "wifi";          // true when the Wi-Fi module ran
}  // namespace run_key

/// Keys of graph.json. An edge: {"from", "to" (keyframe ids), "type" (edge_type), "inliers",
/// "from_to": {"t": [x, y, z], "q_xyzw": [x, y, z, w]} (pose of "to" in the frame of "from"),
/// "information": 36 numbers}; from format version 3 also "pruned" (absent = false: the edge
/// survived the after-run pruning) and "weight" (absent = 1).
namespace graph_key {
inline constexpr const char* kNodes = "nodes";
inline constexpr const char* kEdges = "edges";
inline constexpr const char* kFrom = "from";
inline constexpr const char* kTo = "to";
inline constexpr const char* kType = "type";
inline constexpr const char* kInliers = "inliers";
inline constexpr const char* kFromTo = "from_to";
inline constexpr const char* kTranslation = "t";
inline constexpr const char* kRotationXyzw = "q_xyzw";
inline constexpr const char* kInformation = "information";
inline constexpr const char* kPruned = "pruned";
inline constexpr const char* kWeight = "weight";
}  // namespace graph_key

/// Values of a graph.json edge's "type".
namespace edge_type {
inline constexpr const char* kOdometry = "odometry";
inline constexpr const char* kVisual = "visual";
inline constexpr const char* kLoop = "loop";
inline constexpr const char* kWeak = "weak";
}  // namespace edge_type

/// Keys of timing.json.
namespace timing_key {
inline constexpr const char* kModules = "modules";
inline constexpr const char* kCounters = "counters";
inline constexpr const char* kRoles = "roles";
inline constexpr const char* kKeyframeSearches = "keyframe_searches";
inline constexpr const char* kWallS = "wall_s";
}  // namespace timing_key

/// Wall-clock modules of timing.json. Nested ones: loop_closure_detection contains
/// candidate_selection and the verifications of candidates; wifi_clustering is booked inside
/// whichever module asked for it (scan aggregation outside any).
namespace module {
inline constexpr const char* kFeatureExtraction = "feature_extraction";
inline constexpr const char* kMatching = "matching";
inline constexpr const char* kRansac = "ransac";
inline constexpr const char* kCandidateSelection = "candidate_selection";
inline constexpr const char* kLoopClosureDetection = "loop_closure_detection";
inline constexpr const char* kEdgeAcceptance = "edge_acceptance";
inline constexpr const char* kOptimisation = "optimisation";
inline constexpr const char* kTotal = "total";
/// The Wi-Fi module's overhead (the paper's "Wi-Fi overhead" = the sum of the two).
inline constexpr const char* kWifiClustering = "wifi_clustering";
inline constexpr const char* kWifiClusterManagement = "wifi_cluster_management";
}  // namespace module

/// Deterministic work counters of timing.json.
namespace counter {
inline constexpr const char* kFrames = "frames";
inline constexpr const char* kKeyframes = "keyframes";
inline constexpr const char* kCandidateComparisons = "candidate_comparisons";
inline constexpr const char* kRansacRuns = "ransac_runs";
inline constexpr const char* kAcceptedTransformations = "accepted_transformations";
inline constexpr const char* kLoopClosures = "loop_closures";
inline constexpr const char* kRejectedHypotheses = "rejected_hypotheses";
inline constexpr const char* kOptimisations = "optimisations";
/// Levenberg-Marquardt iterations, summed over every optimisation (a graph torn between
/// conflicting edges takes more before it settles: rgbdslam's optimizer_convergence).
inline constexpr const char* kOptimisationIterations = "optimisation_iterations";
/// Optimisations whose result Ceres called unusable (the poses before it were kept).
inline constexpr const char* kOptimisationFailures = "optimisation_failures";
/// After-run pruning: edges removed, and edges discounted because removal would split the graph.
inline constexpr const char* kPrunedEdges = "pruned_edges";
inline constexpr const char* kDiscountedEdges = "discounted_edges";
inline constexpr const char* kTrackingFailures = "tracking_failures";
/// Keyframes made because tracking against the last one failed (a promoted tracked frame, or a
/// frame without tracking edge): off a front end's keyframe schedule.
inline constexpr const char* kKeyframesAfterTrackingLoss = "keyframes_after_tracking_loss";
inline constexpr const char* kWifiSimilarityComparisons = "wifi_similarity_comparisons";
inline constexpr const char* kWifiUnsignedKeyframes = "wifi_keyframes_without_signature";
inline constexpr const char* kWifiBoundedPool = "wifi_bounded_pool_keyframes";
inline constexpr const char* kWifiClustersFounded = "wifi_clusters_founded";
inline constexpr const char* kWifiClusterJoins = "wifi_cluster_joins";
}  // namespace counter

/// A CSV header line ("a,b,c\n") of a column list (those below, and the front ends' own).
template <std::size_t N>
std::string csv_header(const std::array<const char*, N>& columns) {
  std::string line;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) line += ',';
    line += columns[i];
  }
  return line + '\n';
}

/// Columns of loop_closures.csv, in order: the keyframes (ids, frame indices, stamps), the
/// candidate role that found the closure, its inliers and reprojection error, and the estimated
/// pose of `to` in the camera frame of `from` (t, q).
namespace loop_closures_column {
// clang-format off
inline constexpr std::array<const char*, 16> kAll = {
    "from_keyframe", "to_keyframe", "from_frame", "to_frame", "from_time", "to_time", "role",
    "inliers", "rms_reprojection_px", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
// clang-format on
}  // namespace loop_closures_column

/// Fields of one role's entry in timing.json's "roles".
namespace role_key {
inline constexpr const char* kComparisons = "comparisons";  // visual comparisons tried
inline constexpr const char* kRansacRuns = "ransac_runs";
inline constexpr const char* kVerified = "verified";  // transformation passed verification
inline constexpr const char* kAccepted = "accepted";  // ... and became a graph edge (for
                                                      // "tracking": placed the frame)
inline constexpr const char* kTimeS = "time_s";       // wall-clock of those comparisons
}  // namespace role_key

}  // namespace wifislam::run_folder
