// One site per scene (sim/site/site.hpp): the dataset generator, radio maps, `world` and the demo
// build it in one place, so they see the same access points, walls and shadowing, and radio maps
// default to the height where datasets scan.
#include "sim/site/site.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "radio_model/propagation_model.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_types.hpp"
#include "tests/sim/site/loop_with_ap_seed.hpp"

namespace wifislam::sim {
namespace {

TEST(Site, TheGeneratorAndASiteBuiltAloneSeeTheSameRadio) {
  const scene::Scene scene = scene::load_scene_yaml(test::kLoopWithApSeed, "site_test.yaml");
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
  const scene::Scene scene = scene::load_scene_yaml(test::kLoopWithApSeed, "site_test.yaml");
  EXPECT_EQ(site::Site(scene).receiver_height_m(), 0.7);
}

}  // namespace
}  // namespace wifislam::sim
