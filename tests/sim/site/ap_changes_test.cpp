// Access points that change across sessions (sim/site/ap_changes.hpp), on a building built from
// a scene file with real Embree rays: an AP switched off, moved, re-powered and a new one, each
// from its session on; the building and its other APs as they were; and every bad change a
// located error.
#include "sim/site/ap_changes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/error.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim {
namespace {

const char* kScene = R"(version: 1
seed: 21
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [24, 0]}
corridors:
  - {id: ab, from: A, to: B, rooms: [{side: both}]}
access_points: {placement: random, count: 6)";

scene::Scene scene_with(const std::string& changes, int session) {
  std::string yaml = kScene;
  yaml += changes.empty() ? "}\n" : ",\n  changes: " + changes + "}\n";
  yaml += "route:\n  nodes: [A, B]\n";
  scene::Scene scene = scene::load_scene_yaml(yaml, "changes.yaml");
  scene.session = static_cast<std::uint64_t>(session);
  return scene;
}

const radio_model::AccessPoint* find(const std::vector<radio_model::AccessPoint>& aps, int id) {
  for (const auto& ap : aps)
    if (ap.id == id) return &ap;
  return nullptr;
}

const char* kChanges =
    "[{session: 1, change: off, ap: 2},"
    " {session: 2, change: moved, ap: 4, position_m: [20, 0.5, 2.0]},"
    " {session: 2, change: power, ap: 0, tx_power_step_db: -6},"
    " {session: 3, change: new, position_m: [3, 0.2, 2.5], tx_power_dbm: 15}]";

TEST(ApChanges, EachChangeHoldsFromItsSessionOnAndTheRestIsTheBuildingAsPlaced) {
  const site::Site plain(scene_with("", 0));
  const auto& placed = plain.access_points();
  ASSERT_EQ(placed.size(), 6u);
  std::vector<site::Site> sessions;
  for (int k = 0; k <= 4; ++k) sessions.emplace_back(scene_with(kChanges, k));
  // Session 0 is the building as placed.
  EXPECT_EQ(sessions[0].access_points().size(), placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_EQ(sessions[0].access_points()[i].position_m, placed[i].position_m);
    EXPECT_EQ(sessions[0].access_points()[i].bssids.front().mac, placed[i].bssids.front().mac);
  }
  // Session 1: AP 2 is off, the others as placed.
  const auto& s1 = sessions[1].access_points();
  EXPECT_EQ(s1.size(), 5u);
  EXPECT_EQ(find(s1, 2), nullptr);
  EXPECT_EQ(find(s1, 4)->position_m, placed[4].position_m);
  // Session 2: AP 4 moved (same BSSIDs), AP 0 6 dB weaker.
  const auto& s2 = sessions[2].access_points();
  EXPECT_EQ(find(s2, 4)->position_m, Eigen::Vector3d(20, 0.5, 2.0));
  EXPECT_EQ(find(s2, 4)->bssids.front().mac, placed[4].bssids.front().mac);
  EXPECT_EQ(find(s2, 0)->tx_power_dbm, placed[0].tx_power_dbm - 6.0);
  // Real rays: AP 0's mean RSSI at a spot falls by exactly its power step.
  const Eigen::Vector3d spot(10.0, 0.3, 0.5);
  const auto index_of = [](const site::Site& site, int id) { return *site.radio().index_of(id); };
  const radio_model::Bssid& b0 = placed[0].bssids.front();
  EXPECT_NEAR(sessions[2].radio().mean_rssi_dbm(index_of(sessions[2], 0), b0, spot),
              plain.radio().mean_rssi_dbm(index_of(plain, 0), b0, spot) - 6.0, 1e-9);
  // Session 3: a new AP, id 6, its own BSSIDs; sessions 3 and 4 give it the same ones.
  const auto& s3 = sessions[3].access_points();
  ASSERT_EQ(s3.size(), 6u);
  const radio_model::AccessPoint* added = find(s3, 6);
  ASSERT_NE(added, nullptr);
  EXPECT_EQ(added->tx_power_dbm, 15.0);
  std::set<std::uint64_t> macs;
  for (const auto& ap : s3) macs.insert(ap.base_mac().value);
  EXPECT_EQ(macs.size(), s3.size());
  const auto& later = find(sessions[4].access_points(), 6)->bssids;
  ASSERT_EQ(later.size(), added->bssids.size());
  for (std::size_t k = 0; k < later.size(); ++k) {
    EXPECT_EQ(later[k].mac, added->bssids[k].mac);
    EXPECT_EQ(later[k].channel, added->bssids[k].channel);
  }
  // The new AP is loud near it.
  EXPECT_GT(sessions[3].radio().mean_rssi_dbm(index_of(sessions[3], 6), added->bssids.front(),
                                              Eigen::Vector3d(3.5, 0.2, 0.5)),
            -60.0);
}

TEST(ApChanges, SessionsShareTheBuildingButNotThePausesOrWifiDraws) {
  const site::Site s0(scene_with("", 0)), s1(scene_with("", 1)), again(scene_with("", 1));
  EXPECT_EQ(scene::session_seed(s0.scene()), s0.scene().seed);
  EXPECT_NE(scene::session_seed(s1.scene()), s0.scene().seed);
  ASSERT_EQ(s0.access_points().size(), s1.access_points().size());
  for (std::size_t i = 0; i < s0.access_points().size(); ++i)
    EXPECT_EQ(s0.access_points()[i].position_m, s1.access_points()[i].position_m);
  // The same shadowing: the building's.
  const Eigen::Vector3d spot(12.0, 0.2, 0.5);
  EXPECT_EQ(s0.radio().link(0, spot).shadowing_normal, s1.radio().link(0, spot).shadowing_normal);
  // The robot pauses elsewhere in another session, and at the same spots in the same one.
  // (The first pause is at the start in every session.)
  ASSERT_GT(s0.motion().pauses().size(), 2u);
  ASSERT_GT(s1.motion().pauses().size(), 2u);
  EXPECT_NE(s0.motion().pauses()[1].start, s1.motion().pauses()[1].start);
  EXPECT_EQ(s1.motion().pauses()[1].start, again.motion().pauses()[1].start);
}

TEST(ApChanges, BadChangesAreLocatedAtTheirKeys) {
  const auto rejected = [](const std::string& changes, int session) {
    try {
      site::Site site(scene_with(changes, session));
    } catch (const ParseError& e) {
      return std::string(e.key_path()) + " | " + e.what();
    }
    return std::string("accepted");
  };
  EXPECT_NE(rejected("[{session: 1, change: off}]", 1).find("access_points.changes[0] |"),
            std::string::npos);
  EXPECT_NE(rejected("[{session: 1, change: new, ap: 1, position_m: [3, 0, 2]}]", 0)
                .find("access_points.changes[0].ap"),
            std::string::npos);
  EXPECT_NE(rejected("[{session: 1, change: moved, ap: 1}]", 0).find("needs `position_m`"),
            std::string::npos);
  EXPECT_NE(rejected("[{session: 1, change: off, ap: 9}]", 0).find("no access point 9"),
            std::string::npos);
  EXPECT_NE(rejected("[{session: 1, change: moved, ap: 1, position_m: [300, 0, 2]}]", 0)
                .find("outside the building"),
            std::string::npos);
  EXPECT_NE(rejected("[{session: 1, change: off, ap: 1}, {session: 2, change: power, ap: 1, "
                     "tx_power_step_db: 3}]",
                     2)
                .find("is off from an earlier change"),
            std::string::npos);
  // Read errors: an unknown change and a session before 1, located in the file.
  EXPECT_THROW(scene_with("[{session: 1, change: stolen, ap: 1}]", 0), ParseError);
  EXPECT_THROW(scene_with("[{session: 0, change: off, ap: 1}]", 0), ParseError);
}

TEST(ApChanges, AResolvedSceneKeepsItsSessionAndChanges) {
  const scene::Scene scene = scene_with(kChanges, 2);
  const std::string resolved = scene::resolved_scene_yaml(scene);
  const scene::Scene again = scene::load_scene_yaml(resolved, "resolved.yaml");
  EXPECT_EQ(again.session, std::optional<std::uint64_t>(2));
  ASSERT_EQ(again.access_points.changes.size(), 4u);
  EXPECT_EQ(again.access_points.changes[3].change, scene::AccessPointChangeKind::kNew);
  EXPECT_EQ(scene::resolved_scene_yaml(again), resolved);
  // A scene without sessions writes neither key.
  scene::Scene no_session = scene_with("", 0);
  no_session.session.reset();
  EXPECT_EQ(scene::resolved_scene_yaml(no_session).find("session"), std::string::npos);
  EXPECT_EQ(scene::resolved_scene_yaml(no_session).find("changes"), std::string::npos);
}

// A moved AP stays on its level: its z is above that level's floor, a basement's included.
TEST(ApChanges, AMovedApKeepsItsLevelsFloorBelowGround) {
  const std::string yaml = R"(version: 1
levels:
  - {id: basement, elevation_m: -3.1}
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [24, 0]}
corridors:
  - {id: ab, from: A, to: B}
access_points:
  placement: explicit
  list: [{position_m: [4, 0, 2.5]}]
  changes: [{session: 1, change: moved, ap: 0, position_m: [20, 0, 2.0]}]
route:
  nodes: [A, B]
)";
  scene::Scene scene = scene::load_scene_yaml(yaml, "basement.yaml");
  EXPECT_NEAR(site::Site(scene).access_points().front().position_m.z(), -3.1 + 2.5, 1e-9);
  scene.session = 1;
  const Eigen::Vector3d moved = site::Site(scene).access_points().front().position_m;
  EXPECT_NEAR(moved.x(), 20.0, 1e-9);
  EXPECT_NEAR(moved.z(), -3.1 + 2.0, 1e-9);
}

}  // namespace
}  // namespace wifislam::sim
