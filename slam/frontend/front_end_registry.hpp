#pragma once
// Front ends by name: a small table from the `frontend` option to a constructor, one entry per
// family. Wi-Fi is orthogonal: when the options ask for it, make_front_end() attaches a Wi-Fi
// module to whichever front end it built, so `--wifi` works with every entry.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "slam/frontend/front_end.hpp"
#include "slam/slam_options.hpp"
#include "slam/util/instrumentation.hpp"

namespace wifislam::slam::frontend {

/// What a front end is built from: the run's options, and the run's instrumentation (a front
/// end may time its own modules and count its own work).
struct FrontEndContext {
  const SlamOptions* options = nullptr;
  util::Instrumentation* instrumentation = nullptr;
  bool stream_has_wifi = false;
  bool stream_has_odometry = false;
};

using FrontEndFactory = std::function<std::unique_ptr<FrontEnd>(const FrontEndContext&)>;

/// Adds (or replaces) a front end under `name`. Built in (front_end_registry.cpp's table):
/// "rgbdslam", "rtabmap" and "orbslam"; tests add their own.
void register_front_end(const std::string& name, FrontEndFactory factory);

/// The front end named `context.options->frontend`, holding a Wi-Fi module when
/// `options->wifi.enabled`. Throws InvalidInputError listing the known names when there is none,
/// or when Wi-Fi is asked for and the stream has no scans.
std::unique_ptr<FrontEnd> make_front_end(const FrontEndContext& context);

std::vector<std::string> front_end_names();
/// The names joined with ", " (for messages and --help).
std::string front_end_name_list();

}  // namespace wifislam::slam::frontend
