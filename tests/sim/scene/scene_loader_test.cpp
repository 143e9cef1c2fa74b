// Scene files: every shipped scene loads, every key of the schema is read, and resolved scenes
// round-trip.
#include <gtest/gtest.h>

#include <filesystem>

#include "sim/scene/scene_loader.hpp"

namespace wifislam::sim {
namespace {

std::vector<std::string> shipped_scene_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(WIFISLAM_SCENES_DIR)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedScenes, AllFiveModelledOnThePaperExistAndLoad) {
  const auto files = shipped_scene_files();
  for (const char* name : {"c_hall", "b_hall", "j_hall", "a_hall", "aliasing_ladder"}) {
    const std::string path = std::string(WIFISLAM_SCENES_DIR) + "/" + name + ".yaml";
    const scene::Scene scene = scene::load_scene_file(path);
    EXPECT_EQ(scene.name, name);
    EXPECT_EQ(scene.source_path, path);
    EXPECT_GE(scene.route.nodes.size(), 3u) << name;
  }
  EXPECT_GE(files.size(), 5u);
}

TEST(ShippedScenes, AccessPointCountsFollowThePaper) {
  // Paper, "Datasets": C Hall < 40 APs, B Hall about 40, J Hall about 70, A Hall 45.
  auto count = [](const char* name) {
    return scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/" + name + ".yaml")
        .access_points.count;
  };
  EXPECT_LT(count("c_hall"), 40);
  EXPECT_GE(count("c_hall"), 30);
  EXPECT_NEAR(count("b_hall"), 40, 4);
  EXPECT_NEAR(count("j_hall"), 70, 5);
  EXPECT_EQ(count("a_hall"), 45);
}

TEST(ShippedScenes, AliasingLadderIsWorstCase) {
  const scene::Scene s =
      scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/aliasing_ladder.yaml");
  EXPECT_EQ(s.appearance.aliasing, 1.0);
}

TEST(SceneLoader, ResolvedSceneRoundTripsForEveryShippedScene) {
  for (const auto& path : shipped_scene_files()) {
    const scene::Scene scene = scene::load_scene_file(path);
    const std::string resolved = scene::resolved_scene_yaml(scene);
    const scene::Scene again = scene::load_scene_yaml(resolved, "resolved");
    EXPECT_EQ(scene::resolved_scene_yaml(again), resolved) << path;
    EXPECT_EQ(again.seed, scene.seed);
    EXPECT_EQ(again.corridors.size(), scene.corridors.size());
  }
}

TEST(SceneLoader, ReadsEveryKeyOfTheSchema) {
  // A scene that sets every key to a non-default value; each must arrive in the struct.
  const std::string yaml = R"(
version: 1
name: every_key
description: all keys set
seed: 77
building: {wall_height_m: 3.1, wall_thickness_m: 0.2}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [12, 0]}
corridors:
  - id: c
    from: A
    to: B
    width_m: 2.5
    material: concrete
    rooms:
      - {side: left, from_m: 1, to_m: 11, room_length_m: 5, depth_m: 3, door_offset_m: 2,
         door_width_m: 1.1, doors_open: true, material: glass}
open_areas:
  - id: hall
    polygon_m: [[-5, -5], [0, -5], [0, 5], [-5, 5]]
    material: brick
    pillars: [{center_m: [-2, 0], size_m: 0.5}]
appearance:
  aliasing: 0.25
  segment_length_m: 3
  themes: {wall: brick_paint, door: metal, floor: carpet, ceiling: plain}
  posters_per_10m: 3
  light_spacing_m: 2.5
  landmarks: [{position_m: [4, 1], height_m: 1.2, width_m: 0.8, kind: sign}]
access_points:
  placement: explicit
  count: 1
  seed: 9
  height_m: 2.2
  tx_power_dbm: 17
  ssids_per_radio: 4
  min_spacing_m: 2
  list: [{position_m: [1, 2, 2.5], tx_power_dbm: 15}]
  line_from_m: [0, 0]
  line_to_m: [1, 1]
route:
  nodes: [A, B, A]
  speed_mps: 0.4
  max_yaw_rate_radps: 0.7
  turn_radius_m: 0.5
  min_wall_clearance_m: 0.35
  pause: {spacing_m: [2.5, 3.5], duration_s: 8, scan_while_moving: true}
sensors:
  camera: {width_px: 320, height_px: 240, fx_px: 262.5, fy_px: 262.5, cx_px: 159.5,
           cy_px: 119.5, fps: 15, height_m: 0.6, pitch_deg: -5}
  depth: {min_range_m: 0.5, max_range_m: 5, noise: false, quantisation: false, dropouts: false,
          lateral_noise: true, lateral_noise_base_px: 0.7, lateral_noise_angle_coeff_px: 0.04}
  color: {noise: true, conversion_gain_dn_per_e: 0.08, read_noise_dn: 1.5, auto_exposure: true,
          exposure_target_dn: 100, exposure_time_constant_s: 0.25, exposure_gain_range: [0.5, 8]}
  wifi: {sensitivity_dbm: -90, dwell_per_channel_s: 0.05, scan_interval_s: 3}
  odometry: {rate_hz: 20, noise_per_m: 0.05, noise_per_rad: 0.04, scale_error: 0.02,
             yaw_bias_radpm: 0.001}
radio: {environment: residential, distance_coefficient: 25, shadowing_sigma_db: 5,
        shadowing_decorrelation_m: 4, fast_fading_sigma_db: 1.5, people_disturbance_db: 2}
)";
  const scene::Scene s = scene::load_scene_yaml(yaml, "every_key.yaml");
  EXPECT_EQ(s.name, "every_key");
  EXPECT_EQ(s.description, "all keys set");
  EXPECT_EQ(s.seed, 77u);
  EXPECT_DOUBLE_EQ(s.building.wall_height_m, 3.1);
  EXPECT_DOUBLE_EQ(s.building.wall_thickness_m, 0.2);
  ASSERT_EQ(s.nodes.size(), 2u);
  EXPECT_EQ(s.nodes[1].position_m, Eigen::Vector2d(12, 0));
  const scene::Corridor& c = s.corridors.at(0);
  EXPECT_DOUBLE_EQ(c.width_m, 2.5);
  EXPECT_EQ(c.material, radio_model::WallMaterial::kConcrete);
  const scene::RoomRow& r = c.rooms.at(0);
  EXPECT_EQ(r.side, scene::RoomRow::Side::kLeft);
  EXPECT_DOUBLE_EQ(r.from_m, 1);
  EXPECT_DOUBLE_EQ(r.to_m.value(), 11);
  EXPECT_DOUBLE_EQ(r.room_length_m, 5);
  EXPECT_DOUBLE_EQ(r.depth_m, 3);
  EXPECT_DOUBLE_EQ(r.door_offset_m, 2);
  EXPECT_DOUBLE_EQ(r.door_width_m, 1.1);
  EXPECT_TRUE(r.doors_open);
  EXPECT_EQ(r.material, radio_model::WallMaterial::kGlass);
  const scene::OpenArea& a = s.open_areas.at(0);
  EXPECT_EQ(a.polygon_m.size(), 4u);
  EXPECT_EQ(a.material, radio_model::WallMaterial::kBrick);
  EXPECT_DOUBLE_EQ(a.pillars.at(0).size_m, 0.5);
  EXPECT_DOUBLE_EQ(s.appearance.aliasing, 0.25);
  EXPECT_DOUBLE_EQ(s.appearance.segment_length_m, 3);
  EXPECT_EQ(s.appearance.themes.wall, "brick_paint");
  EXPECT_EQ(s.appearance.themes.door, "metal");
  EXPECT_EQ(s.appearance.themes.floor, "carpet");
  EXPECT_EQ(s.appearance.themes.ceiling, "plain");
  EXPECT_DOUBLE_EQ(s.appearance.posters_per_10m, 3);
  EXPECT_DOUBLE_EQ(s.appearance.light_spacing_m, 2.5);
  EXPECT_EQ(s.appearance.landmarks.at(0).kind, "sign");
  EXPECT_EQ(s.access_points.placement, scene::ApPlacement::kExplicit);
  EXPECT_EQ(s.access_points.seed.value(), 9u);
  EXPECT_DOUBLE_EQ(s.access_points.height_m, 2.2);
  EXPECT_DOUBLE_EQ(s.access_points.tx_power_dbm, 17);
  EXPECT_EQ(s.access_points.ssids_per_radio, 4);
  EXPECT_DOUBLE_EQ(s.access_points.min_spacing_m, 2);
  EXPECT_DOUBLE_EQ(s.access_points.explicit_list.at(0).tx_power_dbm.value(), 15);
  EXPECT_EQ(s.access_points.line_to_m, Eigen::Vector2d(1, 1));
  EXPECT_EQ(s.route.nodes, (std::vector<std::string>{"A", "B", "A"}));
  EXPECT_DOUBLE_EQ(s.route.speed_mps, 0.4);
  EXPECT_DOUBLE_EQ(s.route.max_yaw_rate_radps, 0.7);
  EXPECT_DOUBLE_EQ(s.route.turn_radius_m, 0.5);
  EXPECT_DOUBLE_EQ(s.route.min_wall_clearance_m, 0.35);
  EXPECT_DOUBLE_EQ(s.route.pause.spacing_min_m, 2.5);
  EXPECT_DOUBLE_EQ(s.route.pause.spacing_max_m, 3.5);
  EXPECT_DOUBLE_EQ(s.route.pause.duration_s, 8);
  EXPECT_TRUE(s.route.pause.scan_while_moving);
  EXPECT_EQ(s.sensors.camera.intrinsics.width_px, 320);
  EXPECT_DOUBLE_EQ(s.sensors.camera.intrinsics.cy_px, 119.5);
  EXPECT_DOUBLE_EQ(s.sensors.camera.fps, 15);
  EXPECT_DOUBLE_EQ(s.sensors.camera.pitch_deg, -5);
  EXPECT_FALSE(s.sensors.depth.noise);
  EXPECT_FALSE(s.sensors.depth.quantisation);
  EXPECT_FALSE(s.sensors.depth.dropouts);
  EXPECT_DOUBLE_EQ(s.sensors.depth.max_range_m, 5);
  EXPECT_TRUE(s.sensors.depth.lateral_noise);
  EXPECT_DOUBLE_EQ(s.sensors.depth.lateral_noise_base_px, 0.7);
  EXPECT_DOUBLE_EQ(s.sensors.depth.lateral_noise_angle_coeff_px, 0.04);
  EXPECT_TRUE(s.sensors.color.noise);
  EXPECT_DOUBLE_EQ(s.sensors.color.conversion_gain_dn_per_e, 0.08);
  EXPECT_DOUBLE_EQ(s.sensors.color.read_noise_dn, 1.5);
  EXPECT_TRUE(s.sensors.color.auto_exposure);
  EXPECT_DOUBLE_EQ(s.sensors.color.exposure_target_dn, 100);
  EXPECT_DOUBLE_EQ(s.sensors.color.exposure_time_constant_s, 0.25);
  EXPECT_DOUBLE_EQ(s.sensors.color.exposure_min_gain, 0.5);
  EXPECT_DOUBLE_EQ(s.sensors.color.exposure_max_gain, 8);
  EXPECT_DOUBLE_EQ(s.sensors.wifi.sensitivity_dbm, -90);
  EXPECT_DOUBLE_EQ(s.sensors.wifi.scan_interval_s, 3);
  EXPECT_DOUBLE_EQ(s.sensors.odometry.rate_hz, 20);
  EXPECT_DOUBLE_EQ(s.sensors.odometry.yaw_bias_radpm, 0.001);
  EXPECT_EQ(s.radio.environment, radio_model::RadioEnvironment::kResidential);
  EXPECT_DOUBLE_EQ(s.radio.distance_coefficient.value(), 25);
  EXPECT_DOUBLE_EQ(s.radio.people_disturbance_db, 2);
  // And all of it survives the resolved-scene round trip.
  EXPECT_EQ(scene::resolved_scene_yaml(scene::load_scene_yaml(scene::resolved_scene_yaml(s), "r")),
            scene::resolved_scene_yaml(s));
}

TEST(SceneLoader, AbsentKeysTakeTheDocumentedDefaults) {
  const scene::Scene s = scene::load_scene_yaml(R"(
version: 1
nodes: [{id: A, position_m: [0, 0]}, {id: B, position_m: [10, 0]}]
corridors: [{id: c, from: A, to: B}]
route: {nodes: [A, B]}
)",
                                                "minimal.yaml");
  EXPECT_EQ(s.sensors.camera.intrinsics, CameraIntrinsics::kinect_v1());
  EXPECT_DOUBLE_EQ(s.sensors.camera.fps, 30);
  EXPECT_DOUBLE_EQ(s.sensors.depth.min_range_m, 0.8);
  EXPECT_DOUBLE_EQ(s.sensors.depth.max_range_m, 4.0);
  // The sensor parts added after the pinned datasets are off (scenes/README.md says why).
  EXPECT_FALSE(s.sensors.depth.lateral_noise);
  EXPECT_FALSE(s.sensors.color.noise);
  EXPECT_FALSE(s.sensors.color.auto_exposure);
  EXPECT_DOUBLE_EQ(s.sensors.depth.lateral_noise_base_px, 0.8);
  EXPECT_DOUBLE_EQ(s.sensors.depth.lateral_noise_angle_coeff_px, 0.035);
  EXPECT_DOUBLE_EQ(s.sensors.color.exposure_target_dn, 118);
  EXPECT_DOUBLE_EQ(s.route.speed_mps, 0.5);
  EXPECT_DOUBLE_EQ(s.route.pause.duration_s, 10);
  EXPECT_DOUBLE_EQ(s.sensors.wifi.sensitivity_dbm, -92);
  EXPECT_DOUBLE_EQ(s.corridors[0].width_m, 2.0);
}

}  // namespace
}  // namespace wifislam::sim
