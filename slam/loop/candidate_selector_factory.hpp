#pragma once
// Front ends by name: a small table from the `frontend` option to a constructor, so adding a
// front end (or a Wi-Fi variant) is one registration, not another branch in the pipeline.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "slam/loop/candidate_selector.hpp"
#include "slam/slam_options.hpp"
#include "slam/util/instrumentation.hpp"

namespace wifislam::slam {

/// What a selector is built from: the run's options, and the run's instrumentation (a selector
/// may time its own modules, e.g. Wi-Fi clustering, and count its own work).
struct SelectorContext {
  const SlamOptions* options = nullptr;
  Instrumentation* instrumentation = nullptr;
  bool stream_has_wifi = false;
  bool stream_has_odometry = false;
};

using SelectorFactory = std::function<std::unique_ptr<CandidateSelector>(const SelectorContext&)>;

/// The registry name of the selector `options` ask for: `frontend`, plus "+wifi" when the Wi-Fi
/// module is on.
std::string selector_key(const SlamOptions& options);

/// Adds (or replaces) a front end. Built in: "rgbdslam", "rgbdslam+wifi".
void register_candidate_selector(const std::string& name, SelectorFactory factory);

/// The selector named `context.options->frontend`. Throws InvalidInputError listing the known
/// names when there is none.
std::unique_ptr<CandidateSelector> make_candidate_selector(const SelectorContext& context);

std::vector<std::string> candidate_selector_names();

}  // namespace wifislam::slam
