#include "slam/frontend/front_end.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wifislam::slam {

FrontEnd::FrontEnd(std::unique_ptr<EdgeAcceptance> acceptance)
    : acceptance_(std::move(acceptance)) {
  if (!acceptance_) throw std::logic_error("FrontEnd: an edge acceptance policy is required");
}

FrontEnd::~FrontEnd() = default;

std::string FrontEnd::label() const { return name() + (wifi_ ? "+wifi" : ""); }

void FrontEnd::attach_wifi(std::unique_ptr<WifiModule> module) {
  if (wifi_) throw std::logic_error("FrontEnd: a Wi-Fi module is already attached");
  wifi_ = std::move(module);
  on_wifi_attached();
}

void FrontEnd::observe_wifi_scan(const WifiScan& scan) {
  if (wifi_) wifi_->observe_scan(scan);
}

void FrontEnd::observe_odometry(const OdometryReading& reading) {
  if (wifi_) wifi_->observe_odometry(reading);
  on_odometry(reading);
}

std::vector<Candidate> FrontEnd::candidates_for(const SelectionQuery& query) {
  if (wifi_ && !assigns_wifi_clusters_itself()) wifi_->sign(query.keyframe);
  return select(query);
}

EdgeType FrontEnd::classify(const Candidate& candidate, KeyframeId keyframe,
                            const LoopRule& rule) const {
  return rule.is_loop(candidate.keyframe, keyframe) ? EdgeType::kLoop : EdgeType::kVisual;
}

void FrontEnd::on_verified(const VerificationReport& report) {
  // Cluster management for the keyframe signed by candidates_for() (the module throws if the
  // pipeline reports another one).
  if (wifi_ && !assigns_wifi_clusters_itself()) {
    wifi_->assign(report.keyframe, wifi_connections(report));
  }
  after_verification(report);
}

void FrontEnd::write_outputs(const std::filesystem::path& run_dir) const {
  if (wifi_) wifi_->write_outputs(run_dir);
  write_own_outputs(run_dir);
}

nlohmann::json FrontEnd::own_summary() const { return nlohmann::json::object(); }

nlohmann::json FrontEnd::summary() const {
  nlohmann::json out = own_summary();
  if (wifi_) out["wifi"] = wifi_->summary();
  return out;
}

}  // namespace wifislam::slam
