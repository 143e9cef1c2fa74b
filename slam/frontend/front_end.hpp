#pragma once
// A SLAM front end: the policies where the three families of the paper differ (docs/frontends.md).
// The shared pipeline (slam/system) owns features, tracking, the keyframe decision, visual
// verification, the pose graph and its optimiser, and run output; for each new keyframe it asks the
// front end
//   memory       which keyframes may be compared at all (searchable)
//   candidates   which to verify, in what order, and why (select -> roles)
//   classify     whether a verified match is a loop closure or an ordinary visual edge
//   acceptance   which verified hypotheses become edges (an EdgeAcceptance policy)
// and tells it afterwards what came of them (on_verified).
//
// The Wi-Fi module is not a kind of front end: a front end *holds* one when the run asks for
// Wi-Fi (attach_wifi), sees it through wifi(), and calls it at the paper's points. The base class
// feeds it every scan and odometry reading, runs cluster management after verification for the
// keyframes the front end signed, and writes its outputs; the rest is the front end's.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/sensor_stream.hpp"
#include "core/wifi_scan.hpp"
#include "slam/frontend/candidate.hpp"
#include "slam/frontend/edge_acceptance.hpp"
#include "slam/frontend/keyframe_schedule.hpp"
#include "slam/optimize/edge_pruning.hpp"
#include "slam/optimize/robust_kernel.hpp"
#include "slam/wifi/wifi_module.hpp"

namespace wifislam::slam {

/// How a family's back end copes with wrong edges: a robust kernel in every optimisation and a
/// pruning schedule at the end of the run. The default is plain least squares, no pruning.
struct GraphRobustness {
  RobustKernel kernel;
  PruningSchedule pruning;
};

class FrontEnd {
 public:
  /// `acceptance`: the front end's policy for turning verified hypotheses into edges.
  explicit FrontEnd(std::unique_ptr<EdgeAcceptance> acceptance);
  virtual ~FrontEnd();
  FrontEnd(const FrontEnd&) = delete;
  FrontEnd& operator=(const FrontEnd&) = delete;

  /// The front end's name as given on the command line ("rgbdslam").
  virtual std::string name() const = 0;
  /// name(), plus "+wifi" when a Wi-Fi module is attached (for reports).
  std::string label() const;

  /// Gives the front end its Wi-Fi module (once, before the first event).
  void attach_wifi(std::unique_ptr<WifiModule> module);
  WifiModule* wifi() { return wifi_.get(); }
  const WifiModule* wifi() const { return wifi_.get(); }

  /// Sensor events other than frames, in stream order, before any later frame is processed.
  void observe_wifi_scan(const WifiScan& scan);
  void observe_odometry(const OdometryReading& reading);

  /// Memory: whether `keyframe` may be compared with a new keyframe at all (relocalisation
  /// candidates are filtered by it). Default: every keyframe.
  virtual bool searchable(KeyframeId /*keyframe*/) const { return true; }

  /// Candidates for a new keyframe, in the order they should be verified. Signs the keyframe
  /// with the Wi-Fi module first (Wi-Fi clustering; unless the front end assigns its own
  /// places), so every keyframe is clustered and the module's queries speak of it, then asks
  /// select().
  std::vector<Candidate> candidates_for(const SelectionQuery& query);

  /// Edge type of a verified match of `candidate` with the new keyframe. Default: the pipeline's
  /// loop rule (kLoop when the candidate is far enough back in keyframes and path).
  virtual EdgeType classify(const Candidate& candidate, KeyframeId keyframe,
                            const LoopRule& rule) const;

  /// When the family makes keyframes by time and motion (RTAB-Map's nodes); nullopt: the
  /// pipeline's tracking-quality rule (TrackingOptions).
  virtual std::optional<KeyframeSchedule> keyframe_schedule() const { return std::nullopt; }

  const EdgeAcceptance& acceptance() const { return *acceptance_; }
  /// The family's robust kernel and after-run pruning (the shared optimiser applies them).
  virtual GraphRobustness graph_robustness() const { return {}; }
  /// Incremental optimisation schedule: besides after every keyframe that brought a loop closure
  /// (always), after every n-th keyframe (RGBDSLAMv2's `optimizer_skip_step`); 0: only after loop
  /// closures.
  virtual int optimise_every_keyframes() const { return 0; }
  /// How an incremental optimisation stops: 0, after the pipeline's fixed iteration budget
  /// (PoseGraphOptions::incremental_max_iterations); > 0, in rounds until chi^2 improves by less
  /// than this fraction (RGBDSLAMv2's schedule: slam/optimize/pose_graph_optimizer.hpp).
  virtual double optimisation_convergence() const { return 0.0; }

  /// Called once per new keyframe after its hypotheses were accepted or not. Runs Wi-Fi cluster
  /// management for it (unless the front end assigns its own places), then after_verification().
  void on_verified(const VerificationReport& report);

  /// Extra files for the run folder (wifi_clusters.csv, the front end's own) and the front end's
  /// part of run.json.
  void write_outputs(const std::filesystem::path& run_dir) const;
  nlohmann::json summary() const;

 protected:
  /// The front end's candidate selection (memory and candidate policy) for a new keyframe.
  virtual std::vector<Candidate> select(const SelectionQuery& query) = 0;
  /// True for a front end whose places are not the pipeline's keyframes (RTAB-Map's nodes): it
  /// signs and assigns its own places, and the base class leaves the module alone.
  virtual bool assigns_wifi_clusters_itself() const { return false; }
  /// The keyframes a verified keyframe counts as connected to for cluster management. Default:
  /// its visual and loop edges (paper, "General approach"); an ORB-SLAM-style front end adds its
  /// covisible keyframes (paper, "ORB-SLAM", "Cluster Management").
  virtual std::vector<KeyframeId> wifi_connections(const VerificationReport& report) const {
    return report.visually_connected();
  }
  /// Called once when attach_wifi() gave the front end its module (e.g. to subscribe to it).
  virtual void on_wifi_attached() {}
  virtual void on_odometry(const OdometryReading& /*reading*/) {}
  virtual void after_verification(const VerificationReport& /*report*/) {}
  virtual void write_own_outputs(const std::filesystem::path& /*run_dir*/) const {}
  virtual nlohmann::json own_summary() const;

 private:
  std::unique_ptr<EdgeAcceptance> acceptance_;
  std::unique_ptr<WifiModule> wifi_;
};

}  // namespace wifislam::slam
