#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "radio_model/propagation_model.hpp"
#include "radio_model/shadowing_field.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "tests/radio/test_walls.hpp"

namespace wifislam {
namespace {

std::vector<AccessPoint> aps_along_x(int count, std::uint64_t seed) {
  MacAllocator macs(seed);
  std::vector<AccessPoint> aps;
  for (int i = 0; i < count; ++i)
    aps.push_back(make_access_point(i, Eigen::Vector3d(10.0 * i, 3.0, 2.5), 20.0, 3, seed, macs));
  return aps;
}

Mesh some_walls() {
  Mesh mesh;
  for (int w = 0; w < 6; ++w)
    test::add_wall_x(mesh, 5.0f + 8.0f * w, 0.15f, 15.0f, 2.8f, WallMaterial::kBrick, w, 0.9f);
  return mesh;
}

TEST(WifiScanner, SameSeedGivesIdenticalScansAndDifferentSeedDifferentShadowing) {
  const Mesh mesh = some_walls();
  PropagationOptions opt;
  PropagationModel a(mesh, {0, -15}, {50, 15}, aps_along_x(4, 1), opt, 100);
  PropagationModel b(mesh, {0, -15}, {50, 15}, aps_along_x(4, 1), opt, 100);
  PropagationModel c(mesh, {0, -15}, {50, 15}, aps_along_x(4, 1), opt, 101);
  WifiScanner sa(a, {}, 100), sb(b, {}, 100);
  for (double x = 0; x < 40; x += 3.5) {
    const Eigen::Vector3d p(x, 0.5, 1.0);
    for (int k = 0; k < 3; ++k) {
      const Timestamp t = Timestamp::from_seconds(x + 2.0 * k);
      const WifiScan scan = sa.scan(t, p);
      EXPECT_EQ(scan, sb.scan(t, p));
      EXPECT_FALSE(scan.readings.empty());
    }
  }
  int differ = 0, total = 0;
  for (double x = 0; x < 40; x += 1.0) {
    for (std::size_t ap = 0; ap < 4; ++ap) {
      const Eigen::Vector3d p(x, -2.0, 1.0);
      const double ra = a.link(ap, p).shadowing_db, rc = c.link(ap, p).shadowing_db;
      EXPECT_EQ(ra, b.link(ap, p).shadowing_db);
      differ += std::abs(ra - rc) > 0.1;
      ++total;
    }
  }
  EXPECT_GT(differ, total * 9 / 10);
}

TEST(WifiScanner, ScansTakeDwellTimesChannelsAndReportIntegerRssiAboveTheFloor) {
  PropagationModel model(Mesh{}, {0, -5}, {100, 5}, aps_along_x(10, 2), {}, 7);
  WifiScannerOptions o;
  o.dwell_per_channel_s = 0.1;
  WifiScanner scanner(model, o, 7);
  EXPECT_EQ(scanner.scan_duration_ns(), 2'000'000'000);  // 20 channels x 0.1 s
  const WifiScan s = scanner.scan(Timestamp::from_seconds(5.0), {0, 0, 1});
  EXPECT_EQ(s.start_time, Timestamp::from_seconds(5.0));
  EXPECT_EQ(s.end_time, Timestamp::from_seconds(7.0));
  for (const WifiReading& r : s.readings) {
    EXPECT_GE(r.rssi_dbm, -92);
    EXPECT_LT(r.rssi_dbm, 20);
  }
}

TEST(WifiScanner, DetectionProbabilityFallsNearTheSensitivityFloor) {
  // One AP; find receiver distances where the mean RSSI is 40 dB and 1.5 dB above the floor.
  PropagationOptions opt;
  opt.shadowing_sigma_db = 0.0;
  opt.fast_fading_sigma_db = 0.0;
  PropagationModel model(Mesh{}, {-5, -5}, {400, 5}, aps_along_x(1, 3), opt, 3);
  const Bssid& b = model.access_points()[0].bssids.front();
  auto x_for = [&](double target_dbm) {
    double lo = 1.0, hi = 5000.0;
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (model.mean_rssi_dbm(0, b, Eigen::Vector3d(mid, 3.0, 2.5)) > target_dbm ? lo : hi) = mid;
    }
    return lo;
  };
  WifiScanner scanner(model, {}, 3);
  auto rate = [&](double x) {
    int heard = 0;
    for (int k = 0; k < 400; ++k) {
      const auto s = scanner.scan(Timestamp::from_seconds(2.0 * k), {x, 3.0, 2.5});
      for (const auto& r : s.readings) heard += r.bssid == b.mac;
    }
    return heard / 400.0;
  };
  EXPECT_EQ(rate(x_for(-92.0 + 40.0)), 1.0);
  const double near = rate(x_for(-92.0 + 1.5));
  EXPECT_GT(near, 0.2);
  EXPECT_LT(near, 0.6);  // 1 - exp(-1.5 / 3) = 0.39
  EXPECT_EQ(rate(x_for(-92.0 - 1.0)), 0.0);
}

TEST(WifiScanner, AveragingAPausesScansBeatsOneScan) {
  PropagationModel model(some_walls(), {0, -15}, {50, 15}, aps_along_x(4, 4), {}, 4);
  WifiScanner scanner(model, {}, 4);
  double err_single = 0, err_avg = 0;
  int n = 0;
  for (double x = 1; x < 40; x += 1.5) {
    const Eigen::Vector3d p(x, 1.0, 1.0);
    std::map<std::uint64_t, std::vector<int>> samples;
    for (int k = 0; k < 5; ++k)  // a 10 s pause at 2 s per scan
      for (const auto& r : scanner.scan(Timestamp::from_seconds(100.0 * x + 2.0 * k), p).readings)
        samples[r.bssid.value].push_back(r.rssi_dbm);
    for (std::size_t a = 0; a < 4; ++a) {
      for (const Bssid& b : model.access_points()[a].bssids) {
        const auto it = samples.find(b.mac.value);
        if (it == samples.end() || it->second.size() < 5) continue;
        const double truth = model.mean_rssi_dbm(a, b, p);
        double mean = 0;
        for (int v : it->second) mean += v;
        mean /= it->second.size();
        err_single += std::pow(it->second.front() - truth, 2);
        err_avg += std::pow(mean - truth, 2);
        ++n;
      }
    }
  }
  ASSERT_GT(n, 100);
  const double rms_single = std::sqrt(err_single / n), rms_avg = std::sqrt(err_avg / n);
  EXPECT_NEAR(rms_single, 2.0, 0.4);      // fast fading sigma 2 dB (+ rounding)
  EXPECT_LT(rms_avg, 0.65 * rms_single);  // ~1/sqrt(5)
}

TEST(WifiScanner, PeopleDisturbanceLowersRssiOnAverage) {
  PropagationOptions quiet, busy;
  busy.people_disturbance_db = 10.0;
  PropagationModel mq(Mesh{}, {0, -5}, {50, 5}, aps_along_x(3, 5), quiet, 5);
  PropagationModel mb(Mesh{}, {0, -5}, {50, 5}, aps_along_x(3, 5), busy, 5);
  WifiScanner sq(mq, {}, 5), sb(mb, {}, 5);
  double sum_q = 0, sum_b = 0;
  for (int k = 0; k < 200; ++k) {
    const Timestamp t = Timestamp::from_seconds(2.0 * k);
    for (const auto& r : sq.scan(t, {12, 0, 1}).readings) sum_q += r.rssi_dbm;
    for (const auto& r : sb.scan(t, {12, 0, 1}).readings) sum_b += r.rssi_dbm;
  }
  EXPECT_LT(sum_b, sum_q);
}

TEST(ShadowingField, HasTheRequestedSigmaAndExponentialCorrelation) {
  const double sigma = 4.0, L = 3.0;
  ShadowingField field({0, 0}, {300, 300}, sigma, L, Rng::stream(9, "test"));
  double s2 = 0, c1 = 0, c4 = 0;
  int n = 0;
  for (double y = 5; y < 295; y += 7.0) {
    for (double x = 5; x < 280; x += 7.0) {
      const double v = field.at_db({x, y});
      s2 += v * v;
      c1 += v * field.at_db({x + L, y});
      c4 += v * field.at_db({x + 4 * L, y});
      ++n;
    }
  }
  EXPECT_NEAR(std::sqrt(s2 / n), sigma, 0.3);
  EXPECT_NEAR(c1 / s2, std::exp(-1.0), 0.08);
  EXPECT_NEAR(c4 / s2, std::exp(-4.0), 0.08);
  // Deterministic and zero when disabled.
  ShadowingField again({0, 0}, {300, 300}, sigma, L, Rng::stream(9, "test"));
  EXPECT_EQ(field.at_db({17.3, 42.1}), again.at_db({17.3, 42.1}));
  EXPECT_EQ(ShadowingField({0, 0}, {10, 10}, 0.0, L, Rng::stream(9, "test")).at_db({1, 1}), 0.0);
}

}  // namespace
}  // namespace wifislam
