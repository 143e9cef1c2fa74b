// A survey by several phones: calibration recovers the RSS offset each was simulated with, and a
// phone left out of the fit is served better once its offset is measured at a few spots.
//
// The survey is simulated on c_hall through the radio model's own PropagationModel (real Embree
// wall counts, its shadowing fields) and read by each device through ReceiverDevice::reported_dbm,
// the map the scanner applies: "phone_a" is the reference, "phone_b" reads 5.5 dB low (the size
// of the offset between two phones the issue reports), "phone_c" 3 dB high. Every AP is heard
// everywhere (calibration_recovery_test.cpp says why censoring is left out). phone_a surveys
// every spot of a 1.5 m lattice, phone_b every other row of it, and phone_c (held out) every
// third spot.
//
// Tolerances, from the scene's seed and 7 others (AP placement and shadowing fields change with
// it): phone_b's offset came out 0.03 to 0.08 dB above the truth, with a 95 % half width (widened
// for shadowing shared between positions) of 0.06 dB. The error is one-sided: phone_b's spots
// are a subset of the rows, and the linear model's small misfit there (it has no term for what
// the fitted materials leave over) lands in the offset, which the intervals do not cover. Checked:
// within 0.25 dB, a quarter of a phone's 1 dB step, and a half width below 1 dB. The held-out
// phone's offset, from 5 positions, came out within 0.36 dB (checked: 1.5 dB), and lowered its
// residual rms from 5.2-5.3 to 4.3-4.4 dB (checked: lower).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "radio_model/calibrate/calibration_report.hpp"
#include "radio_model/calibrate/correlated_intervals.hpp"
#include "radio_model/calibrate/propagation_fit.hpp"
#include "radio_model/calibrate/rss_survey.hpp"
#include "radio_model/calibrate/shadowing_statistics.hpp"
#include "radio_model/calibrate/survey_links.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/receiver_device.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"
#include "sim/site/survey_site.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/world_types.hpp"
#include "tests/radio_model/calibrate/simulated_survey.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::radio_model::calibrate {
namespace {

namespace fs = std::filesystem;

constexpr double kOffsetBDb = -5.5, kOffsetCDb = 3.0;

TEST(DeviceOffsetRecovery, EachPhonesOffsetIsRecoveredAndAHeldOutPhoneGainsFromItsOwn) {
  sim::scene::Scene scene =
      sim::scene::load_scene_file(std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml");
  scene.radio.distance_coefficient = 30.0;
  scene.radio.shadowing_sigma_db = 4.0;
  scene.radio.shadowing_decorrelation_m = 3.0;
  scene.access_points.tx_power_dbm = 20.0;
  const sim::site::Site site(scene);
  const PropagationModel& model = site.radio();

  ReceiverDevice phone_b, phone_c;
  phone_b.rss_offset_db = kOffsetBDb;
  phone_c.rss_offset_db = kOffsetCDb;
  const fs::path path = test::scratch_folder() / "device_survey.csv";
  {
    std::ofstream out(path);
    out << "device,x_m,y_m,ap_id,rss_dbm\n";  // columns in another order than usual
    const sim::world::FloorPlan& plan = site.world().plan;
    Rng fading = Rng::stream(11, "test/fading");
    int spot = 0, row = 0;
    for (double y = std::floor(plan.bounds_min_m.y()) + 0.25; y <= plan.bounds_max_m.y();
         y += 1.5, ++row) {
      for (double x = std::floor(plan.bounds_min_m.x()) + 0.25; x <= plan.bounds_max_m.x();
           x += 1.5) {
        if (!sim::world::regions_contain(plan.free_space, {x, y})) continue;
        ++spot;
        const Eigen::Vector3d p(x, y, test::kSurveyReceiverHeightM);
        for (std::size_t i = 0; i < model.access_points().size(); ++i) {
          const RadioLink link = model.link(i, p);
          const double mean = model.access_points()[i].tx_power_dbm -
                              model.path_loss_db(link, test::kSurveyFrequencyMhz) -
                              model.shadowing_db(link, RadioBand::k2_4GHz);
          const int id = model.access_points()[i].id;
          for (int k = 0; k < 5; ++k) {
            out << fmt::format("phone_a,{},{},{},{:.2f}\n", x, y, id,
                               ReceiverDevice{}.reported_dbm(mean + fading.normal(0.0, 2.0)));
            if (row % 2 == 0)
              out << fmt::format("phone_b,{},{},{},{:.2f}\n", x, y, id,
                                 phone_b.reported_dbm(mean + fading.normal(0.0, 2.0)));
            if (spot % 3 == 0)
              out << fmt::format("phone_c,{},{},{},{:.2f}\n", x, y, id,
                                 phone_c.reported_dbm(mean + fading.normal(0.0, 2.0)));
          }
        }
      }
    }
  }
  Survey survey = read_survey(path.string(), SurveyFormat::kLong, test::kSurveyReceiverHeightM);
  fs::remove(path);
  std::vector<std::string> devices = survey.devices();
  std::sort(devices.begin(), devices.end());
  EXPECT_EQ(devices, (std::vector<std::string>{"phone_a", "phone_b", "phone_c"}));
  Survey held = survey;
  std::erase_if(survey.samples, [](const SurveySample& s) { return s.device == "phone_c"; });
  std::erase_if(held.samples, [](const SurveySample& s) { return s.device != "phone_c"; });

  std::vector<SurveyAccessPoint> aps;
  for (const auto& ap : site.access_points()) aps.push_back({ap.id, ap.position_m, {}, ""});
  const SurveySite where = sim::site::survey_site(site);
  // phone_b as the reference: phone_a's offset is then +5.5.
  const SurveyLinks b_first =
      survey_links(survey, aps, where, devices_reference_first(survey, "phone_b"));
  ASSERT_EQ(b_first.devices.front(), "phone_b");
  const SurveyLinks links = survey_links(survey, aps, where);
  ASSERT_EQ(links.devices, (std::vector<std::string>{"phone_a", "phone_b"}));  // first seen first

  const WallLossTable defaults(scene.building.wall_thickness_m);
  const LinearRadioModel before =
      scene_model(links, defaults, std::nullopt, 20.0, test::kSurveyFrequencyMhz);
  PropagationFit fit = fit_propagation(links, before.wall_loss_db);
  const ShadowingStatistics s = shadowing_statistics(links, fit.model, fit.parameters);
  widen_for_correlated_shadowing(fit, links, s);
  ASSERT_EQ(fit.model.device_offset_db.size(), 2u);
  EXPECT_EQ(fit.model.device_offset_db[0], 0.0);
  const double b = fit.model.device_offset_db[1], b_ci = fit.device_offset_ci95_db[1];
  EXPECT_NEAR(b, kOffsetBDb, 0.25) << "95 % CI +-" << b_ci;
  EXPECT_GT(b_ci, 0.0);
  EXPECT_LT(b_ci, 1.0);
  const PropagationFit from_b = fit_propagation(b_first, before.wall_loss_db);
  EXPECT_NEAR(from_b.model.device_offset_db[1], -b, 1e-6);  // the same fit, seen from phone_b

  const LinearRadioModel baseline = fit_log_distance(links);
  const HeldOutDeviceScore h =
      score_held_out_device(survey_links(held, aps, where, {"phone_c"}), fit.model, baseline, 5);
  EXPECT_EQ(h.device, "phone_c");
  EXPECT_GT(h.scored_samples, 500);
  EXPECT_NEAR(h.offset_db, kOffsetCDb, 1.5);
  EXPECT_LT(h.rms_with_offset_db, h.rms_without_offset_db);
  EXPECT_LT(h.log_distance_rms_with_offset_db, h.log_distance_rms_db);

  Calibration c;
  c.scene_name = scene.name;
  c.survey_path = "simulated";
  c.train = links;
  c.before = before;
  c.fit = fit;
  c.baseline = baseline;
  c.shadowing = s;
  c.held_out = h;
  const std::string md = calibration_report_markdown(c);
  EXPECT_NE(md.find("| phone_b |"), std::string::npos) << md;
  EXPECT_NE(md.find("Held-out device `phone_c`"), std::string::npos) << md;
  EXPECT_NE(calibration_scene_yaml(c).find("#   phone_b: rss_offset_db"), std::string::npos);
  if (::testing::Test::HasFailure()) std::cerr << md;
}

}  // namespace
}  // namespace wifislam::radio_model::calibrate
