// A building of two levels, from a scene file to a radio map: the map of the lower level hears
// an access point placed on the upper level, weaker than the same link without the slab by
// exactly the slab's loss under itu_walls and by ITU-R P.1238's floor penetration factor under
// itu_site_general. Expected losses are computed here from the cited sources, not read from the
// model's tables: 3GPP TR 38.901 Table 7.4.3-1's concrete, 5 + 4 f_GHz dB; P.1238-7 Table 3's
// office rows, 14 dB at 2.4 GHz and 16 dB at 5.2 GHz for one floor. Real Embree rays throughout.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_map.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/site/site.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::sim {
namespace {

// The same corridor with rooms on both levels; the only AP is on the upper level, over the
// corridor. No shadowing or spread: the map is the path loss alone.
std::string two_level_scene(const std::string& model) {
  return R"(version: 1
building: {wall_height_m: 2.8}
levels:
  - {id: ground}
  - {id: upper, slab_thickness_m: 0.25, slab_material: concrete}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [16, 0]}
  - {id: A1, position_m: [0, 0], level: upper}
  - {id: B1, position_m: [16, 0], level: upper}
corridors:
  - {id: ab, from: A, to: B, rooms: [{side: both}]}
  - {id: ab1, from: A1, to: B1, rooms: [{side: left}]}
access_points:
  placement: explicit
  list:
    - {position_m: [8, 0, 2.5], level: upper}
route:
  nodes: [A, B]
radio:
  model: )" +
         model + R"(
  environment: office
  shadowing_sigma_db: 0
  bssid_spread_db: 0
  people_disturbance_db: 0
)";
}

double tr38901_concrete_db(double frequency_mhz) { return 5.0 + 4.0 * frequency_mhz * 1e-3; }
double p1238_office_one_floor_db(double frequency_mhz) {
  return frequency_mhz < 4000.0 ? 14.0 : 16.0;
}

/// The building's walls without its slabs: the same link with no floor in the way.
radio_model::WallMesh without_slabs(radio_model::WallMesh walls) {
  std::erase_if(walls.faces, [](const radio_model::WallMesh::Face& f) { return f.slab; });
  return walls;
}

double radio_frequency_mhz(const radio_model::AccessPoint& ap, radio_model::RadioBand band) {
  for (const radio_model::Bssid& b : ap.bssids)
    if (b.band == band) return b.frequency_mhz();
  ADD_FAILURE() << "the AP has no radio in that band";
  return 0.0;
}

/// Compares the lower level's map with and without the slab, cell by cell, where the link
/// crosses the slab and no wall; returns how many cells were compared.
int compare_lower_level_maps(const std::string& model,
                             double (*expected_drop_db)(double frequency_mhz)) {
  const scene::Scene scene = scene::load_scene_yaml(two_level_scene(model), "two_levels.yaml");
  const site::Site site(scene);
  const world::World& world = site.world();
  EXPECT_EQ(world.storeys.size(), 2u);
  const world::Storey* ground = world.storey("ground");
  EXPECT_NE(ground, nullptr);
  if (!ground) return 0;
  EXPECT_EQ(world.level_id, "ground");
  EXPECT_EQ(site.access_points().size(), 1u);
  const radio_model::AccessPoint& ap = site.access_points().front();
  EXPECT_DOUBLE_EQ(ap.position_m.z(), 2.8 + 0.25 + 2.5);  // the upper floor at 3.05 m

  Eigen::Vector2d bounds_min_m, bounds_max_m;
  world::building_bounds(world, bounds_min_m, bounds_max_m);
  const radio_model::PropagationModel no_slab(without_slabs(world::radio_wall_mesh(world)),
                                              bounds_min_m, bounds_max_m, site.access_points(),
                                              site::propagation_options(scene), scene.seed);
  int compared = 0, heard = 0;
  for (const auto band : {radio_model::RadioBand::k2_4GHz, radio_model::RadioBand::k5GHz}) {
    radio_model::RadioMapOptions options;
    options.resolution_m = 0.5;
    options.ap_id = ap.id;
    options.band = band == radio_model::RadioBand::k2_4GHz ? radio_model::RadioMapBand::k2_4GHz
                                                           : radio_model::RadioMapBand::k5GHz;
    options.receiver_height_m = site.receiver_height_m();
    const radio_model::RadioMap with =
        site::compute_radio_map(site.radio(), ground->plan, options, ground->elevation_m);
    const radio_model::RadioMap without =
        site::compute_radio_map(no_slab, ground->plan, options, ground->elevation_m);
    const double drop_db = expected_drop_db(radio_frequency_mhz(ap, band));
    for (int row = 0; row < with.rows; ++row) {
      for (int col = 0; col < with.cols; ++col) {
        if (!std::isfinite(with.at(col, row))) continue;
        if (with.at(col, row) > -92.0f) ++heard;  // above the scanner's default sensitivity
        const Eigen::Vector2d xy = with.cell_center_m(col, row);
        const Eigen::Vector3d rx(xy.x(), xy.y(), ground->elevation_m + options.receiver_height_m);
        // Links through the slab and no wall, with it and without it. (A link that runs from a
        // wall straight into the slab the wall stands on crosses one stretch of material, named
        // after the face it enters first: embree_wall_scene.hpp's counting rule.)
        const radio_model::RadioLink link = site.radio().link(0, rx);
        if (link.wall_count() != 0.0 || link.slabs_crossed != 1) continue;
        if (!no_slab.link(0, rx).line_of_sight()) continue;
        EXPECT_NEAR(without.at(col, row) - with.at(col, row), drop_db, 1e-3)
            << model << " at (" << xy.x() << ", " << xy.y() << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(heard, 100) << "the lower level hears the AP upstairs";
  return compared;
}

TEST(TwoLevelRadio, UnderItuWallsTheLowerLevelHearsTheUpperApThroughExactlyTheSlabsLoss) {
  // The corridor under the AP is 16 m x 2 m: at 0.5 m cells, over a hundred cells per band.
  EXPECT_GT(compare_lower_level_maps("itu_walls", tr38901_concrete_db), 200);
}

TEST(TwoLevelRadio, UnderItuSiteGeneralTheFloorCostsP1238sFactor) {
  EXPECT_GT(compare_lower_level_maps("itu_site_general", p1238_office_one_floor_db), 200);
}

TEST(TwoLevelRadio, TheRouteLevelIsInItsOwnFrameAndTheStoreysInTheBuildings) {
  const scene::Scene scene =
      scene::load_scene_yaml(two_level_scene("itu_walls"), "two_levels.yaml");
  const site::Site site(scene);
  const world::World& world = site.world();
  ASSERT_EQ(world.storeys.size(), 2u);
  const world::Storey& upper = world.storeys[1];
  EXPECT_EQ(upper.level_id, "upper");
  EXPECT_DOUBLE_EQ(upper.elevation_m, 3.05);
  // The upper storey's mesh is raised to its elevation; the route level's stays at its floor.
  float upper_min_z = 1e9f, route_min_z = 1e9f;
  for (const auto& p : upper.mesh.positions_m) upper_min_z = std::min(upper_min_z, p.z());
  for (const auto& p : world.mesh.positions_m) route_min_z = std::min(route_min_z, p.z());
  EXPECT_NEAR(upper_min_z, 3.05f, 1e-5f);
  EXPECT_EQ(route_min_z, 0.0f);
  // The two levels differ: the upper has rooms on one side only.
  EXPECT_LT(upper.plan.rooms.size(), world.storeys[0].plan.rooms.size());
  // The slab is in the radio's walls, once, with its six faces on one wall id.
  const radio_model::WallMesh walls = world::radio_wall_mesh(world);
  int slab_faces = 0;
  std::set<int> slab_ids;
  for (const auto& face : walls.faces)
    if (face.slab) ++slab_faces, slab_ids.insert(face.wall_id);
  EXPECT_EQ(slab_faces, 12);
  EXPECT_EQ(slab_ids.size(), 1u);
  // A link from a room below, through its wall's top and up through the storey above, crosses
  // that wall: the storeys' walls are closed at their tops. Without the slab it is the only
  // crossing; with it, wall and slab are one stretch of material.
  const radio_model::PropagationModel no_slab(without_slabs(walls), world.plan.bounds_min_m,
                                              world.plan.bounds_max_m, site.access_points(),
                                              site::propagation_options(scene), scene.seed);
  const Eigen::Vector3d in_room_below(8.0, 1.95, 0.5);  // 0.8 m past the 0.15 m wall at y = 1
  EXPECT_EQ(no_slab.link(0, in_room_below).wall_count(), 1.0);
  EXPECT_EQ(no_slab.link(0, in_room_below).slabs_crossed, 0);
}

}  // namespace
}  // namespace wifislam::sim
