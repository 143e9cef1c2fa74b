#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>

#include "radio_model/propagation_model.hpp"
#include "radio_model/wifi_scanner.hpp"
#include "tests/radio_model/test_access_points.hpp"
#include "tests/radio_model/test_walls.hpp"

namespace wifislam::radio_model {
namespace {

using test::aps_along_x;

WallMesh some_walls() {
  WallMesh mesh;
  for (int w = 0; w < 6; ++w)
    test::add_wall_x(mesh, 5.0f + 8.0f * w, 0.15f, 15.0f, 2.8f, WallMaterial::kBrick, w, 0.9f);
  return mesh;
}

TEST(WifiScanner, SameSeedGivesIdenticalScansAndDifferentSeedDifferentShadowing) {
  const WallMesh mesh = some_walls();
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
      const double ra = a.link(ap, p).shadowing_normal, rc = c.link(ap, p).shadowing_normal;
      EXPECT_EQ(ra, b.link(ap, p).shadowing_normal);
      differ += std::abs(ra - rc) > 0.1;
      ++total;
    }
  }
  EXPECT_GT(differ, total * 9 / 10);
}

TEST(WifiScanner, ScansTakeDwellTimesChannelsAndReportIntegerRssiAboveTheFloor) {
  PropagationModel model(WallMesh{}, {0, -5}, {100, 5}, aps_along_x(10, 2), {}, 7);
  WifiScannerOptions o;
  o.device.dwell_per_channel_s = 0.1;
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
  opt.bssid_spread_db = 0.0;
  PropagationModel model(WallMesh{}, {-5, -5}, {400, 5}, aps_along_x(1, 3), opt, 3);
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
    // 4000 scans: the rate's standard error is below 0.008, so 0.035 is over 4 of them. Scans
    // start 2.0123457 s apart, so their phase against the 102.4 ms beacon interval spreads evenly
    // (at exactly 2 s it would take only 32 values).
    for (int k = 0; k < 4000; ++k) {
      const auto s = scanner.scan(Timestamp::from_seconds(2.0123457 * k), {x, 3.0, 2.5});
      for (const auto& r : s.readings) heard += r.bssid == b.mac;
    }
    return heard / 4000.0;
  };
  // Far above the floor only beacon timing misses: 1 - 100 / 102.4 of the dwells hold no beacon.
  const double in_dwell = 0.1 / 0.1024;
  EXPECT_NEAR(rate(x_for(-92.0 + 40.0)), in_dwell, 0.01);
  const double near = rate(x_for(-92.0 + 1.5));
  EXPECT_NEAR(near, in_dwell * (1 - std::exp(-1.5 / 3)), 0.035);  // 0.977 x 0.39
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
  // One scan: radio fading 2 dB, BSSID spread 0.5 dB, integer rounding 0.29 dB.
  const PropagationOptions& o = model.options();
  const double rounding2 = 1.0 / 12.0;
  const double single2 = std::pow(o.fast_fading_sigma_db, 2) + std::pow(o.bssid_spread_db, 2);
  EXPECT_NEAR(rms_single, std::sqrt(single2 + rounding2), 0.3);
  // Five scans 2 s apart: the fading's variance falls by sum_ij rho^|i-j| / 25 with
  // rho = exp(-2 s / coherence), not by 1/5 as for independent scans.
  double correlated_share = 0.0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      correlated_share += std::exp(-2.0 * std::abs(i - j) / o.fading_coherence_s);
  correlated_share /= 25.0;
  const double avg2 = std::pow(o.fast_fading_sigma_db, 2) * correlated_share +
                      std::pow(o.bssid_spread_db, 2) / 5.0 + rounding2 / 5.0;
  EXPECT_NEAR(rms_avg, std::sqrt(avg2), 0.25);
  EXPECT_LT(rms_avg, 0.8 * rms_single);
  EXPECT_GT(rms_avg, std::sqrt(single2 / 5.0));  // worse than independent scans would give
}

// The radio model of fading: the BSSIDs of one radio read nearly the same RSSI in a scan; at a
// still receiver a radio's fading correlates as exp(-dt / coherence) over scans dt apart; scans a
// metre apart are independent (Clarke: J0(2 pi d / lambda) is within +-0.11 of zero beyond 1 m).
// Statistics pooled over 40 APs (80 radios), so they test the process, not one realisation.
TEST(WifiScanner, FadingIsPerRadioAndCorrelatedOverTimeAtAStillReceiver) {
  PropagationOptions opt;
  opt.shadowing_sigma_db = 0.0;
  MacAllocator macs(6);
  std::vector<AccessPoint> aps;
  for (int i = 0; i < 40; ++i)  // all within 12 m of the receivers: every beacon is strong
    aps.push_back(
        make_access_point(i, Eigen::Vector3d(3.0 * (i % 8), 2.0 * (i / 8), 2.5), 20.0, 3, 6, macs));
  PropagationModel model(WallMesh{}, {-5, -5}, {30, 15}, aps, opt, 6);
  WifiScanner scanner(model, {}, 6);
  // residual[(scan, mac)] = reading - mean RSSI
  auto residuals = [&](Timestamp t, const Eigen::Vector3d& p) {
    std::map<std::uint64_t, double> r;
    for (const WifiReading& reading : scanner.scan(t, p).readings) {
      for (std::size_t a = 0; a < aps.size(); ++a)
        for (const Bssid& b : model.access_points()[a].bssids)
          if (b.mac == reading.bssid)
            r[b.mac.value] = reading.rssi_dbm - model.mean_rssi_dbm(a, b, p);
    }
    return r;
  };
  // Within one scan: two BSSIDs of one radio differ by the spread only.
  double within2 = 0.0, across2 = 0.0;
  int within_n = 0;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d p(1.0 + 1.3 * k, 5.0, 1.0);
    const auto r = residuals(Timestamp::from_seconds(50.0 * k), p);
    for (const AccessPoint& ap : model.access_points()) {
      const auto first = r.find(ap.bssids[0].mac.value), second = r.find(ap.bssids[1].mac.value);
      const auto other = r.find(ap.bssids[3].mac.value);  // the 5 GHz radio
      if (first == r.end() || second == r.end() || other == r.end()) continue;
      within2 += std::pow(first->second - second->second, 2);
      across2 += std::pow(first->second - other->second, 2);
      ++within_n;
    }
  }
  ASSERT_GT(within_n, 600);
  const double within_rms = std::sqrt(within2 / within_n),
               across_rms = std::sqrt(across2 / within_n);
  // sqrt(2 (0.5^2 + 1/12)) = 0.82 dB within a radio; sqrt(2 (2^2 + ...)) = 2.9 dB across radios.
  EXPECT_NEAR(within_rms, std::sqrt(2 * (0.25 + 1.0 / 12.0)), 0.2);
  EXPECT_NEAR(across_rms, std::sqrt(2 * (4.0 + 0.25 + 1.0 / 12.0)), 0.35);

  // Over time at one spot, and across a metre.
  auto correlation = [&](double dt_s, const Eigen::Vector3d& offset) {
    double sxy = 0, sxx = 0, syy = 0;
    for (int k = 0; k < 60; ++k) {
      const Eigen::Vector3d p(1.0 + 0.37 * k, 1.0 + 0.23 * k, 1.0);
      const Timestamp t = Timestamp::from_seconds(1000.0 * k);
      const auto a = residuals(t, p),
                 b = residuals(Timestamp::from_seconds(t.seconds() + dt_s), p + offset);
      for (const auto& [mac, x] : a) {
        const auto y = b.find(mac);
        if (y == b.end()) continue;
        sxy += x * y->second;
        sxx += x * x;
        syy += y->second * y->second;
      }
    }
    return sxy / std::sqrt(sxx * syy);
  };
  const double tau = opt.fading_coherence_s;
  const double total2 = 4.0 + 0.25 + 1.0 / 12.0;  // the spread and rounding never correlate
  for (const double dt : {2.0, 4.0, 8.0}) {
    EXPECT_NEAR(correlation(dt, Eigen::Vector3d::Zero()), 4.0 * std::exp(-dt / tau) / total2, 0.07)
        << "scans " << dt << " s apart";
  }
  EXPECT_NEAR(correlation(2.0, {1.0, 0.0, 0.0}), 0.0, 0.1);
  EXPECT_NEAR(correlation(2.0, {0.6, 0.8, 0.0}), 0.0, 0.1);
}

TEST(WifiScanner, ShortDwellsMissBeaconsAtTheIntervalRatio) {
  PropagationOptions opt;
  opt.shadowing_sigma_db = 0.0;
  PropagationModel model(WallMesh{}, {-5, -5}, {50, 5}, aps_along_x(3, 8), opt, 8);
  for (const double dwell_s : {0.05, 0.1, 0.11}) {
    WifiScannerOptions o;
    o.device.dwell_per_channel_s = dwell_s;
    WifiScanner scanner(model, o, 8);
    int heard = 0, possible = 0;
    for (int k = 0; k < 300; ++k) {
      heard += static_cast<int>(
          scanner.scan(Timestamp::from_seconds(3.1 * k), {10, 0, 1}).readings.size());
      possible += 3 * 6;  // every BSSID is 10-20 m away in free space: far above the floor
    }
    EXPECT_NEAR(static_cast<double>(heard) / possible, std::min(1.0, dwell_s / 0.1024), 0.02)
        << "dwell " << dwell_s << " s";
  }
}

TEST(WifiScanner, PeopleDisturbanceLowersRssiOnAverage) {
  PropagationOptions quiet, busy;
  busy.people_disturbance_db = 10.0;
  PropagationModel mq(WallMesh{}, {0, -5}, {50, 5}, aps_along_x(3, 5), quiet, 5);
  PropagationModel mb(WallMesh{}, {0, -5}, {50, 5}, aps_along_x(3, 5), busy, 5);
  WifiScanner sq(mq, {}, 5), sb(mb, {}, 5);
  double sum_q = 0, sum_b = 0;
  for (int k = 0; k < 200; ++k) {
    const Timestamp t = Timestamp::from_seconds(2.0 * k);
    for (const auto& r : sq.scan(t, {12, 0, 1}).readings) sum_q += r.rssi_dbm;
    for (const auto& r : sb.scan(t, {12, 0, 1}).readings) sum_b += r.rssi_dbm;
  }
  EXPECT_LT(sum_b, sum_q);
}

}  // namespace
}  // namespace wifislam::radio_model
