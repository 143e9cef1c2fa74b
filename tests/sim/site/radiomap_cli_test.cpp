// `wifislam radiomap` through the command line, on the site a dataset of the same scene sees.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/sim/site/loop_with_ap_seed.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam::sim {
namespace {

// `wifislam radiomap` without --height maps at the camera height, where the dataset's scans are.
TEST(RadioMapCli, WithoutAHeightMapsAtTheCameraHeight) {
  const std::filesystem::path dir = test::scratch_folder();
  test::write_file(dir / "scene.yaml", test::kLoopWithApSeed);
  auto map_csv = [&](const std::string& extra, const std::string& name) {
    const test::CliResult r =
        test::run_wifislam("radiomap " + (dir / "scene.yaml").string() +
                               " --strongest --res 0.5 -o " + (dir / (name + ".png")).string() +
                               " --csv " + (dir / (name + ".csv")).string() + " " + extra,
                           dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return test::read_file(dir / (name + ".csv"));
  };
  const std::string by_default = map_csv("", "default");
  ASSERT_FALSE(by_default.empty());
  EXPECT_EQ(by_default, map_csv("--height 0.7", "camera"));
  EXPECT_NE(by_default, map_csv("--height 1.0", "one_metre"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wifislam::sim
