#pragma once
// What a front end may want to hear besides its candidate queries: that it was given a Wi-Fi
// module (to subscribe to its cluster events), and what came of each keyframe's verified
// hypotheses (to update its memory, covisibility or loop bookkeeping). Defaults do nothing.

namespace wifislam::slam::frontend {

struct VerificationReport;

class FrontEndEvents {
 public:
  virtual ~FrontEndEvents() = default;

 protected:
  /// Once, when attach_wifi() gave the front end its module.
  virtual void on_wifi_attached() {}
  /// Once per new keyframe, after its hypotheses were accepted or not (and after Wi-Fi cluster
  /// management placed it).
  virtual void after_verification(const VerificationReport& /*report*/) {}
};

}  // namespace wifislam::slam::frontend
