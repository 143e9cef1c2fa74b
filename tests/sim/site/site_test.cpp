// One site per scene (sim/site/site.hpp): the dataset generator, radio maps, `world` and the demo
// build it in one place, so they see the same access points, walls and shadowing, and radio maps
// default to the height where datasets scan.
#include "sim/site/site.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "radio_model/propagation_model.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_types.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

// A small loop whose access points have their own placement seed, as the demo's radio map once
// mishandled: it seeded the shadowing from access_points.seed, the dataset from the scene seed.
constexpr const char* kLoopWithApSeed = R"(version: 1
name: site_test
seed: 21
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [9, 0]}
  - {id: C, position_m: [9, 6]}
  - {id: D, position_m: [0, 6]}
corridors:
  - {id: s, from: A, to: B}
  - {id: e, from: B, to: C}
  - {id: n, from: C, to: D}
  - {id: w, from: D, to: A}
access_points: {placement: random, count: 5, seed: 4}
route: {nodes: [A, B, C, D, A]}
sensors: {camera: {height_m: 0.7}}
)";

TEST(Site, TheGeneratorAndASiteBuiltAloneSeeTheSameRadio) {
  const scene::Scene scene = scene::load_scene_yaml(kLoopWithApSeed, "site_test.yaml");
  const site::Site site(scene);
  generate::GenerateOptions options;
  options.camera = sim::generate::CameraOutput::kNoImages;
  const generate::GenerationPipeline pipeline(scene, options);
  ASSERT_EQ(site.access_points().size(), 5u);
  ASSERT_EQ(pipeline.radio().access_points().size(), 5u);
  const radio_model::PropagationModel seeded_by_ap_seed(
      sim::world::radio_wall_mesh(site.world().mesh), site.world().plan.bounds_min_m,
      site.world().plan.bounds_max_m, site.access_points(), sim::site::propagation_options(scene),
      sim::site::access_point_seed(scene));
  int differs_from_ap_seed = 0;
  for (std::size_t i = 0; i < site.access_points().size(); ++i) {
    EXPECT_EQ(site.access_points()[i].position_m, pipeline.radio().access_points()[i].position_m);
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(1, 0.2, 0.7), Eigen::Vector3d(8.5, 3, 0.7),
                                     Eigen::Vector3d(4, 6.3, 0.7)}) {
      const radio_model::RadioLink a = site.radio().link(i, p);
      const radio_model::RadioLink b = pipeline.radio().link(i, p);
      EXPECT_EQ(a.shadowing_normal, b.shadowing_normal);
      EXPECT_EQ(a.walls_per_material, b.walls_per_material);
      differs_from_ap_seed += a.shadowing_normal != seeded_by_ap_seed.link(i, p).shadowing_normal;
    }
  }
  // The shadowing comes from the scene seed, as datasets have it, not from the placement seed.
  EXPECT_GT(differs_from_ap_seed, 0);
}

TEST(Site, TheReceiverRidesWithTheCamera) {
  const scene::Scene scene = scene::load_scene_yaml(kLoopWithApSeed, "site_test.yaml");
  EXPECT_EQ(site::Site(scene).receiver_height_m(), 0.7);
}

// `wifislam radiomap` without --height maps at the camera height, where the dataset's scans are.
TEST(Site, RadioMapCommandDefaultsToTheCameraHeight) {
  const std::filesystem::path dir = test::scratch_folder();
  std::ofstream(dir / "scene.yaml") << kLoopWithApSeed;
  auto map_csv = [&](const std::string& extra, const std::string& name) {
    const std::string cmd = std::string(WIFISLAM_BINARY) + " radiomap " +
                            (dir / "scene.yaml").string() + " --strongest --res 0.5 -o " +
                            (dir / (name + ".png")).string() + " --csv " +
                            (dir / (name + ".csv")).string() + " " + extra + " > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
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
