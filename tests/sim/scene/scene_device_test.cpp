// sensors.wifi.device: a shipped name, a device file beside the scene, or a mapping; each bad
// device is a located error, and a resolved scene carries its device in full.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "sim/scene/scene_loader.hpp"
#include "tests/sim/scene/scene_text.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::sim {
namespace {

namespace fs = std::filesystem;

const char* kScene = R"(version: 1
nodes:
  - {id: A, position_m: [0, 0]}
  - {id: B, position_m: [10, 0]}
corridors:
  - {id: ab, from: A, to: B}
route:
  nodes: [A, B]
sensors:
  wifi: {scan_interval_s: 3}
)";

std::string with_wifi(const std::string& wifi_block) {
  return test::replace(kScene, "wifi: {scan_interval_s: 3}", wifi_block);
}

/// A folder of its own for files a test writes, removed with the fixture.
class SceneDeviceFiles : public ::testing::Test {
 protected:
  SceneDeviceFiles() : dir_(wifislam::test::scratch_folder()) {
    fs::create_directories(dir_ / "devices");
  }
  fs::path write(const std::string& relative, const std::string& text) {
    std::ofstream(dir_ / relative) << text;
    return dir_ / relative;
  }
  fs::path dir_;
};

TEST(SceneDevice, WithoutADeviceTheReceiverIsTheReferenceWithTheBlocksKeys) {
  const scene::Scene plain = scene::load_scene_yaml(kScene, "plain.yaml");
  EXPECT_FALSE(plain.sensors.wifi.device);
  EXPECT_EQ(scene::receiver_device(plain.sensors.wifi).name, "reference");
  const scene::Scene tuned = scene::load_scene_yaml(
      with_wifi("wifi: {sensitivity_dbm: -85, dwell_per_channel_s: 0.05}"), "tuned.yaml");
  const radio_model::ReceiverDevice d = scene::receiver_device(tuned.sensors.wifi);
  EXPECT_EQ(d.sensitivity_dbm, -85.0);
  EXPECT_EQ(d.dwell_per_channel_s, 0.05);
  // The resolved scene of a scene without a device keeps the block's own keys only.
  EXPECT_EQ(scene::resolved_scene_yaml(plain).find("device"), std::string::npos);
}

TEST(SceneDevice, AShippedNameLoadsThatDeviceAndTheResolvedSceneWritesItInFull) {
  const scene::Scene s = scene::load_scene_yaml(
      with_wifi("wifi: {device: weaker_phone, scan_interval_s: 3}"), "named.yaml");
  ASSERT_TRUE(s.sensors.wifi.device);
  EXPECT_EQ(s.sensors.wifi.device->name, "weaker_phone");
  EXPECT_EQ(s.sensors.wifi.device->rss_offset_db, -5.0);
  EXPECT_EQ(s.sensors.wifi.scan_interval_s, 3.0);
  const std::string resolved = scene::resolved_scene_yaml(s);
  EXPECT_NE(resolved.find("rss_offset_db: -5"), std::string::npos) << resolved;
  const scene::Scene again = scene::load_scene_yaml(resolved, "resolved.yaml");
  ASSERT_TRUE(again.sensors.wifi.device);
  EXPECT_EQ(again.sensors.wifi.device->name, "weaker_phone");
  EXPECT_EQ(again.sensors.wifi.device->source, s.sensors.wifi.device->source);
  EXPECT_EQ(scene::resolved_scene_yaml(again), resolved);
}

TEST(SceneDevice, AnInlineDeviceSetsEveryKey) {
  const scene::Scene s = scene::load_scene_yaml(
      with_wifi("wifi:\n    device: {name: lab_laptop, source: measured, rss_offset_db: 3.5,\n"
                "             rss_gain: 0.9, sensitivity_dbm: -95, quantisation_db: 2,\n"
                "             dwell_per_channel_s: 0.12, bands: 5GHz,\n"
                "             scan_throttle: android_foreground}"),
      "inline.yaml");
  const radio_model::ReceiverDevice d = *s.sensors.wifi.device;
  EXPECT_EQ(d.name, "lab_laptop");
  EXPECT_EQ(d.source, "measured");
  EXPECT_EQ(d.rss_offset_db, 3.5);
  EXPECT_EQ(d.rss_gain, 0.9);
  EXPECT_EQ(d.sensitivity_dbm, -95.0);
  EXPECT_EQ(d.quantisation_db, 2);
  EXPECT_EQ(d.dwell_per_channel_s, 0.12);
  EXPECT_EQ(d.bands, radio_model::DeviceBands::k5GHzOnly);
  EXPECT_EQ(d.scan_throttle, radio_model::ScanThrottle::kAndroidForeground);
}

TEST_F(SceneDeviceFiles, ADeviceFileIsReadRelativeToTheScenesFolder) {
  write("devices/phone.yaml", "name: my_phone\nsource: two-phone survey\nrss_offset_db: -6\n");
  const fs::path scene =
      write("scene.yaml", with_wifi("wifi: {device: devices/phone.yaml, scan_interval_s: 3}"));
  const scene::Scene s = scene::load_scene_file(scene.string());
  ASSERT_TRUE(s.sensors.wifi.device);
  EXPECT_EQ(s.sensors.wifi.device->name, "my_phone");
  EXPECT_EQ(s.sensors.wifi.device->rss_offset_db, -6.0);
  // The same file by load_receiver_device, as `generate --device` reads it.
  EXPECT_EQ(scene::load_receiver_device((dir_ / "devices/phone.yaml").string()).rss_offset_db,
            -6.0);
}

TEST_F(SceneDeviceFiles, AnErrorInADeviceFileNamesThatFileItsLineAndKey) {
  write("devices/bad.yaml", "name: bad\nrss_ofset_db: -6\n");
  const fs::path scene =
      write("scene.yaml", with_wifi("wifi: {device: devices/bad.yaml, scan_interval_s: 3}"));
  try {
    scene::load_scene_file(scene.string());
    FAIL() << "a bad device file loaded";
  } catch (const ParseError& e) {
    EXPECT_NE(e.where().find("bad.yaml:2:1"), std::string::npos) << e.what();
    EXPECT_EQ(e.key_path(), "rss_ofset_db");
    EXPECT_NE(std::string(e.what()).find("rss_offset_db"), std::string::npos) << e.what();
  }
  write("devices/range.yaml", "name: r\nrss_gain: 3\n");
  EXPECT_THROW(scene::load_receiver_device((dir_ / "devices/range.yaml").string()), ParseError);
  write("devices/nameless.yaml", "rss_gain: 1.1\n");
  EXPECT_THROW(scene::load_receiver_device((dir_ / "devices/nameless.yaml").string()), ParseError);
}

TEST(SceneDevice, BadDevicesAreLocatedInTheScene) {
  const auto unknown = test::expect_parse_error(
      with_wifi("wifi: {device: weaker_phon, scan_interval_s: 3}"), "scene.yaml");
  EXPECT_EQ(unknown.where(), "scene.yaml:10:18");
  EXPECT_EQ(unknown.key_path(), "sensors.wifi.device");
  EXPECT_NE(std::string(unknown.what()).find("weaker_phone"), std::string::npos)
      << unknown.what();  // did you mean

  const auto missing = test::expect_parse_error(
      with_wifi("wifi: {device: no/such/phone.yaml, scan_interval_s: 3}"), "scene.yaml");
  EXPECT_EQ(missing.key_path(), "sensors.wifi.device");
  EXPECT_NE(std::string(missing.what()).find("no device file"), std::string::npos);

  const auto both = test::expect_parse_error(
      with_wifi("wifi: {device: esp32, sensitivity_dbm: -80}"), "scene.yaml");
  EXPECT_EQ(both.key_path(), "sensors.wifi.sensitivity_dbm");
  EXPECT_NE(std::string(both.what()).find("esp32"), std::string::npos);

  const auto band =
      test::expect_parse_error(with_wifi("wifi: {device: {name: x, bands: 6GHz}}"), "scene.yaml");
  EXPECT_EQ(band.key_path(), "sensors.wifi.device.bands");

  const auto step = test::expect_parse_error(
      with_wifi("wifi: {device: {name: x, quantisation_db: 0.5}}"), "scene.yaml");
  EXPECT_EQ(step.key_path(), "sensors.wifi.device.quantisation_db");

  const auto list = test::expect_parse_error(with_wifi("wifi: {device: [esp32]}"), "scene.yaml");
  EXPECT_EQ(list.key_path(), "sensors.wifi.device");
}

}  // namespace
}  // namespace wifislam::sim
