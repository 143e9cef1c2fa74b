// `generate --device`: the same building, route and seed read by another receiver. Scans draw
// from streams named by their start time, so a scan two devices both make is the same air: a
// throttled phone's scans are the reference's at the times it was granted, and a phone that reads
// 5 dB low reports each BSSID 5 dB below the reference.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/dataset_calibration.hpp"
#include "core/wifi_csv.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/read_file.hpp"

namespace wifislam {
namespace {

namespace fs = std::filesystem;

class DeviceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = test::scratch_folder();
    // 10 s pauses every 3-4 m: five scan requests a pause, many more than four in two minutes.
    scene_ = test::tiny_loop_with(scratch_, "duration_s: 1.0", "duration_s: 10.0", "tiny.yaml");
  }
  void TearDown() override { fs::remove_all(scratch_); }

  /// Generates the scene with `device` ("" for the scene's own) and returns the dataset folder.
  fs::path generate(const std::string& device, const std::string& name) {
    const fs::path out = scratch_ / name;
    const auto r =
        test::run_wifislam("generate " + scene_.string() + " --no-images -q -o " + out.string() +
                               (device.empty() ? "" : " --device " + device),
                           scratch_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }
  static std::map<std::string, std::string> scanner_calibration(const fs::path& dataset) {
    std::map<std::string, std::string> out;
    for (const CalibrationGroup& g :
         read_calibration_yaml(dataset / "calibration.yaml").sensor_model)
      if (g.name == "wifi_scanner")
        for (const auto& [key, value] : g.values) out[key] = value;
    return out;
  }
  static nlohmann::json manifest(const fs::path& dataset) {
    return nlohmann::json::parse(test::read_file(dataset / "manifest.json"));
  }

  fs::path scratch_, scene_;
};

TEST_F(DeviceCli, AThrottledPhoneScansTheReferencesScansAtTheTimesItWasGranted) {
  const fs::path reference = generate("", "reference");
  const fs::path phone = generate("android_foreground", "phone");
  const auto all = read_wifi_csv((reference / "wifi.csv").string());
  const auto kept = read_wifi_csv((phone / "wifi.csv").string());
  ASSERT_GT(all.size(), 12u);
  ASSERT_GE(kept.size(), 4u);
  EXPECT_LT(kept.size(), all.size() / 2);
  std::map<std::int64_t, const WifiScan*> by_start;
  for (const WifiScan& s : all) by_start[s.start_time.ns] = &s;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    ASSERT_TRUE(by_start.count(kept[i].start_time.ns)) << "a scan the reference never made";
    EXPECT_EQ(kept[i], *by_start.at(kept[i].start_time.ns));
    std::size_t in_window = 0;
    for (std::size_t j = i; j < kept.size(); ++j)
      in_window += kept[j].start_time.ns - kept[i].start_time.ns <= 120'000'000'000;
    EXPECT_LE(in_window, 4u);
  }
  // The dataset says which device it is and how many requests its throttle refused.
  EXPECT_EQ(scanner_calibration(phone).at("device"), "android_foreground");
  EXPECT_EQ(scanner_calibration(phone).at("scan_throttle"), "android_foreground");
  EXPECT_EQ(scanner_calibration(reference).at("device"), "reference");
  const nlohmann::json m = manifest(phone), r = manifest(reference);
  EXPECT_EQ(m["parameters"]["wifi_device"]["name"], "android_foreground");
  const auto requests = [](const nlohmann::json& j) {
    return j["counts"]["wifi_scans"].get<int>() +
           j["counts"]["wifi_scans_that_heard_nothing"].get<int>() +
           j["counts"]["wifi_scan_requests_throttled"].get<int>();
  };
  EXPECT_EQ(r["counts"]["wifi_scan_requests_throttled"], 0);
  EXPECT_GT(m["counts"]["wifi_scan_requests_throttled"].get<int>(), 0);
  EXPECT_EQ(requests(m), requests(r));
}

TEST_F(DeviceCli, ADeviceFileThatReadsLowReportsEveryBssidItHearsThatMuchLower) {
  test::write_file(scratch_ / "low.yaml",
                   "name: low_phone\nsource: test\nrss_offset_db: -7\nsensitivity_dbm: -99\n");
  const fs::path reference = generate("", "reference");
  const fs::path low = generate((scratch_ / "low.yaml").string(), "low");
  const auto a = read_wifi_csv((reference / "wifi.csv").string());
  const auto b = read_wifi_csv((low / "wifi.csv").string());
  ASSERT_EQ(a.size(), b.size());  // the floor moved with the offset: the same scans hear
  std::size_t readings = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].readings.size(), b[i].readings.size());
    for (std::size_t k = 0; k < a[i].readings.size(); ++k) {
      EXPECT_EQ(b[i].readings[k].bssid, a[i].readings[k].bssid);
      EXPECT_EQ(b[i].readings[k].rssi_dbm, a[i].readings[k].rssi_dbm - 7);
      ++readings;
    }
  }
  EXPECT_GT(readings, 100u);
  EXPECT_EQ(scanner_calibration(low).at("rss_offset_db"), "-7");
  EXPECT_EQ(scanner_calibration(low).at("device"), "low_phone");
}

TEST_F(DeviceCli, ABadDeviceIsALocatedErrorAndWritesNothing) {
  test::write_file(scratch_ / "bad.yaml", "name: bad\nsource: test\nquantisation_db: 0\n");
  const auto bad_file = test::run_wifislam("generate " + scene_.string() + " --no-images -o " +
                                               (scratch_ / "out1").string() + " --device " +
                                               (scratch_ / "bad.yaml").string(),
                                           scratch_);
  test::expect_located_bad_input(bad_file, "bad.yaml:3", "quantisation_db");
  EXPECT_FALSE(fs::exists(scratch_ / "out1"));
  EXPECT_FALSE(fs::exists(scratch_ / "out1.partial"));

  const auto unknown = test::run_wifislam("generate " + scene_.string() + " --no-images -o " +
                                              (scratch_ / "out2").string() + " --device esp33",
                                          scratch_);
  EXPECT_EQ(unknown.exit_code, 2) << unknown.err;
  EXPECT_NE(unknown.err.find("--device"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("esp32"), std::string::npos) << unknown.err;  // did you mean
  EXPECT_FALSE(fs::exists(scratch_ / "out2"));
}

}  // namespace
}  // namespace wifislam
