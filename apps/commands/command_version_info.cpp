// `wifislam info`: versions of the libraries this build uses (useful in bug reports).
#include <fmt/core.h>
#include <Eigen/Core>

#include "apps/command_registry.hpp"

WIFISLAM_COMMAND(info, 90) {
  CLI::App* app = parent.add_subcommand("info", "Print the build's version and library versions.");
  app->callback([] {
    fmt::print("wifislam {}\n", WIFISLAM_VERSION);
    fmt::print("Eigen {}.{}.{}\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
    fmt::print("scenes: {}\n", WIFISLAM_SCENES_DIR);
  });
}
