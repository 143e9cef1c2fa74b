#pragma once
// A SLAM front end: the policies where the three families of the paper differ (docs/frontends.md).
// The shared pipeline (slam/system) owns features, tracking, the keyframe decision, visual
// verification, the pose graph and its optimiser, and run output; for each new keyframe it asks the
// front end
//   memory       which keyframes may be compared at all (searchable)
//   candidates   which to verify, in what order, and why (select -> roles)
//   acceptance   which verified hypotheses become edges (an EdgeAcceptance policy)
// and tells it afterwards what came of them (on_verified).
//
// A front end is put together from small parts, one concern each:
//   CandidatePolicy  memory and candidates, the one concern every front end implements
//   EdgeAcceptance   an object the front end hands over (slam/frontend/edge_acceptance.hpp)
//   FrontEndSchedule data: keyframe making, robust kernel, pruning, optimisation schedule
//   FrontEndEvents   optional: Wi-Fi module attached, a keyframe's verification done
//   FrontEndOutputs  optional: its own run-folder files and run.json summary
// Whether a verified match is a loop closure or an ordinary visual edge is the pipeline's
// LoopRule for every family.
//
// The Wi-Fi module is not a kind of front end: a front end *holds* one when the run asks for
// Wi-Fi (attach_wifi), sees it through wifi(), and calls it at the paper's points. The base class
// feeds it every scan and odometry reading, runs cluster management after verification for the
// keyframes the front end signed, and writes its outputs; the rest is the front end's.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/sensor_stream.hpp"
#include "core/wifi_scan.hpp"
#include "slam/frontend/candidate.hpp"
#include "slam/frontend/candidate_policy.hpp"
#include "slam/frontend/edge_acceptance.hpp"
#include "slam/frontend/front_end_events.hpp"
#include "slam/frontend/front_end_outputs.hpp"
#include "slam/frontend/front_end_schedule.hpp"
#include "slam/wifi/wifi_module.hpp"

namespace wifislam::slam::frontend {

class FrontEnd : public CandidatePolicy, protected FrontEndEvents, protected FrontEndOutputs {
 public:
  /// `name`: as given on the command line ("rgbdslam"). `acceptance`: the front end's policy
  /// for turning verified hypotheses into edges. `schedule`: its keyframe and back-end constants.
  FrontEnd(std::string name, std::unique_ptr<EdgeAcceptance> acceptance,
           FrontEndSchedule schedule = {});
  ~FrontEnd() override;
  FrontEnd(const FrontEnd&) = delete;
  FrontEnd& operator=(const FrontEnd&) = delete;

  const std::string& name() const { return name_; }
  /// name(), plus "+wifi" when a Wi-Fi module is attached (for reports).
  std::string label() const;
  const EdgeAcceptance& acceptance() const { return *acceptance_; }
  const FrontEndSchedule& schedule() const { return schedule_; }

  /// Gives the front end its Wi-Fi module (once, before the first event).
  void attach_wifi(std::unique_ptr<wifi::WifiModule> module);
  wifi::WifiModule* wifi() { return wifi_.get(); }
  const wifi::WifiModule* wifi() const { return wifi_.get(); }

  /// Sensor events other than frames, in stream order, before any later frame is processed: the
  /// Wi-Fi module (when attached) hears them.
  void observe_wifi_scan(const WifiScan& scan);
  void observe_odometry(const OdometryReading& reading);

  /// Candidates for a new keyframe, in the order they should be verified. Signs the keyframe
  /// with the Wi-Fi module first (Wi-Fi clustering), so every keyframe is clustered and the
  /// module's queries speak of it, then asks select().
  std::vector<Candidate> candidates_for(const SelectionQuery& query);

  /// Called once per new keyframe after its hypotheses were accepted or not. Runs Wi-Fi cluster
  /// management for it, then after_verification(). The keyframes it counts as connected are its
  /// visual and loop edges (paper, "General approach"); for the ORB-SLAM family these are also
  /// its covisible keyframes, since covisibility here is weighted by those edges' inliers.
  void on_verified(const VerificationReport& report);

  /// Extra files for the run folder (wifi_clusters.csv, the front end's own) and the front end's
  /// part of run.json.
  void write_outputs(const std::filesystem::path& run_dir) const;
  nlohmann::json summary() const;

 private:
  std::string name_;
  std::unique_ptr<EdgeAcceptance> acceptance_;
  FrontEndSchedule schedule_;
  std::unique_ptr<wifi::WifiModule> wifi_;
};

}  // namespace wifislam::slam::frontend
