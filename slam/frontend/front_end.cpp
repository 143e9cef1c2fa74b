#include "slam/frontend/front_end.hpp"

#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

namespace wifislam::slam::frontend {

nlohmann::json FrontEndOutputs::own_summary() const { return nlohmann::json::object(); }

FrontEnd::FrontEnd(std::string name, std::unique_ptr<EdgeAcceptance> acceptance,
                   FrontEndSchedule schedule)
    : name_(std::move(name)), acceptance_(std::move(acceptance)), schedule_(std::move(schedule)) {
  if (!acceptance_) throw std::logic_error("FrontEnd: an edge acceptance policy is required");
}

FrontEnd::~FrontEnd() = default;

std::string FrontEnd::label() const { return name_ + (wifi_ ? "+wifi" : ""); }

void FrontEnd::attach_wifi(std::unique_ptr<wifi::WifiModule> module) {
  if (wifi_) throw std::logic_error("FrontEnd: a Wi-Fi module is already attached");
  wifi_ = std::move(module);
  on_wifi_attached();
}

void FrontEnd::observe_wifi_scan(const WifiScan& scan) {
  if (wifi_) wifi_->observe_scan(scan);
}

void FrontEnd::observe_odometry(const OdometryReading& reading) {
  if (wifi_) wifi_->observe_odometry(reading);
}

std::vector<Candidate> FrontEnd::candidates_for(const SelectionQuery& query) {
  if (wifi_) wifi_->sign(query.keyframe);
  return select(query);
}

void FrontEnd::on_verified(const VerificationReport& report) {
  // Cluster management for the keyframe signed by candidates_for() (the module throws if the
  // pipeline reports another one).
  if (wifi_) wifi_->assign(report.keyframe, report.visually_connected());
  after_verification(report);
}

void FrontEnd::write_outputs(const std::filesystem::path& run_dir) const {
  if (wifi_) wifi_->write_outputs(run_dir);
  write_own_outputs(run_dir);
}

nlohmann::json FrontEnd::summary() const {
  nlohmann::json out = own_summary();
  if (wifi_) out["wifi"] = wifi_->summary();
  return out;
}

}  // namespace wifislam::slam::frontend
