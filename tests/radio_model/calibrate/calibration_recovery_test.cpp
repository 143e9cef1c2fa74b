// Calibration recovers the constants a survey was simulated with: the c_hall scene with N = 30,
// brick walls of 9 dB, shadowing sigma 4 dB over 3 m and 2 dB fast fading, surveyed on a 1 m
// lattice over all its free space through the simulator's own PropagationModel (same walls, same
// shadowing fields), written as our survey CSV and read back.
//
// Every AP is heard everywhere (no sensitivity cut): censoring the weak links biases a fit of
// means (brick 8.3 dB instead of 8.9 on this survey with a -90 dBm cut: the far links that are
// still heard are the lucky ones), a property of the data, not of the estimator under test.
//
// Tolerances, from the scene's seed and 10 others (AP placement and shadowing fields change with
// it): N came out 29.1-31.9 (sd 0.75; its 95 % interval, allowing for shadowing shared between
// positions, is +-1.3, and +-0.33 if the rows are taken as independent), brick 8.8-9.1 dB, sigma
// 3.8-4.0 dB, decorrelation 2.4-2.8 m (of 3: the AP intercepts absorb some of the long-range
// correlation), fast fading 2.00 dB, mean tx power up to 1.6 dB off (it moves with N). Checked:
// N +-2, brick +-1 dB, sigma +-0.6 dB, fast fading +-0.2 dB, decorrelation 1.5-6 m, mean tx
// power +-2 dB.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

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
#include "sim/scene/scene_loader.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/site/site.hpp"
#include "sim/site/survey_site.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/world_types.hpp"
#include "tests/radio_model/calibrate/simulated_survey.hpp"
#include "tests/support/read_file.hpp"
#include "tests/support/scratch_folder.hpp"

namespace wifislam::radio_model::calibrate {
namespace {

namespace fs = std::filesystem;

constexpr double kTrueN = 30.0, kTrueBrickDb = 9.0, kTrueSigmaDb = 4.0, kTrueFadingDb = 2.0;
constexpr double kTrueDecorrelationM = 3.0, kTxDbm = 20.0, kSensitivityDbm = -130.0;
constexpr int kScansPerSpot = 10;

class CalibrationRecovery : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_path_ = std::string(WIFISLAM_SCENES_DIR) + "/c_hall.yaml";
    sim::scene::Scene scene = sim::scene::load_scene_file(scene_path_);
    scene.radio.distance_coefficient = kTrueN;
    scene.radio.shadowing_sigma_db = kTrueSigmaDb;
    scene.radio.shadowing_decorrelation_m = kTrueDecorrelationM;
    scene.access_points.tx_power_dbm = kTxDbm;
    // Every material flat in frequency, brick at the value to recover; the others at values of
    // their own so that a material mixed up with brick shows.
    const double losses_db[] = {4.0, kTrueBrickDb, 12.0, 2.5, 5.5};  // WallMaterial order
    for (int m = 0; m < 5; ++m) scene.radio.wall_loss_db.by_material_db[m] = losses_db[m];
    site_ = new sim::site::Site(scene);
    const radio_model::PropagationModel& model = site_->radio();

    // The survey: every free lattice spot, 10 scans of every AP heard there.
    survey_path_ = test::scratch_folder("survey") / "survey.csv";
    std::ofstream out(survey_path_);
    out << "x_m,y_m,ap_id,rss_dbm\n";
    const sim::world::FloorPlan& plan = site_->world().plan;
    Rng fading = Rng::stream(7, "test/fading");
    // Spots off the whole metres, where walls of the scene lie.
    for (double y = std::floor(plan.bounds_min_m.y()) + 0.25; y <= plan.bounds_max_m.y();
         y += 1.0) {
      for (double x = std::floor(plan.bounds_min_m.x()) + 0.25; x <= plan.bounds_max_m.x();
           x += 1.0) {
        if (!sim::world::regions_contain(plan.free_space, {x, y})) continue;
        const Eigen::Vector3d p(x, y, test::kSurveyReceiverHeightM);
        for (std::size_t i = 0; i < model.access_points().size(); ++i) {
          const radio_model::RadioLink link = model.link(i, p);
          const double mean = model.access_points()[i].tx_power_dbm -
                              model.path_loss_db(link, test::kSurveyFrequencyMhz) -
                              model.shadowing_db(link, radio_model::RadioBand::k2_4GHz);
          if (mean < kSensitivityDbm) continue;  // not heard at this spot
          for (int k = 0; k < kScansPerSpot; ++k) {
            out << fmt::format("{},{},{},{:.2f}\n", x, y, model.access_points()[i].id,
                               mean + fading.normal(0.0, kTrueFadingDb));
          }
        }
      }
    }
  }
  static void TearDownTestSuite() {
    delete site_;
    fs::remove(survey_path_);
  }

  static std::string scene_path_;
  static fs::path survey_path_;
  static sim::site::Site* site_;
};

std::string CalibrationRecovery::scene_path_;
fs::path CalibrationRecovery::survey_path_;
sim::site::Site* CalibrationRecovery::site_ = nullptr;

TEST_F(CalibrationRecovery, RecoversDistanceCoefficientBrickLossAndShadowing) {
  const sim::scene::Scene& scene = site_->scene();
  std::vector<SurveyAccessPoint> aps;
  for (const auto& ap : site_->access_points()) aps.push_back({ap.id, ap.position_m, {}, ""});
  const Survey survey =
      read_survey(survey_path_, SurveyFormat::kLong, test::kSurveyReceiverHeightM);
  const SurveyLinks links = survey_links(survey, aps, sim::site::survey_site(*site_));
  ASSERT_GT(links.groups.size(), 5000u);

  // Fitted against the default laws (what a user's scene has), not the truth.
  const radio_model::WallLossTable defaults(scene.building.wall_thickness_m);
  const LinearRadioModel before =
      scene_model(links, defaults, std::nullopt, kTxDbm, test::kSurveyFrequencyMhz);
  PropagationFit fit = fit_propagation(links, before.wall_loss_db);
  const ShadowingStatistics s = shadowing_statistics(links, fit.model, fit.parameters);
  const double independent_ci95 = fit.distance_coefficient_ci95;
  widen_for_correlated_shadowing(fit, links, s);
  // Shared shadowing widens N's interval about fourfold (0.33 -> 1.3 on c_hall), in line with
  // the spread of N between shadowing draws.
  EXPECT_GT(fit.distance_coefficient_ci95, 2.5 * independent_ci95);
  EXPECT_LT(fit.distance_coefficient_ci95, 3.0);

  const MaterialFit& brick = fit.materials[static_cast<int>(radio_model::WallMaterial::kBrick)];
  ASSERT_TRUE(brick.fitted) << brick.reason;
  EXPECT_NEAR(fit.model.distance_coefficient, kTrueN, 2.0);
  EXPECT_NEAR(brick.loss_db, kTrueBrickDb, 1.0);
  EXPECT_GT(brick.ci95_db, 0.0);
  EXPECT_NEAR(s.shadowing_sigma_db, kTrueSigmaDb, 0.6);
  EXPECT_NEAR(s.fast_fading_sigma_db, kTrueFadingDb, 0.2);
  EXPECT_GT(s.decorrelation_m, 1.5);
  EXPECT_LT(s.decorrelation_m, 6.0);
  double tx_sum = 0.0;
  int heard = 0;
  for (double intercept : fit.model.intercept_dbm) {
    if (!std::isfinite(intercept)) continue;
    tx_sum += tx_from_intercept_dbm(intercept, test::kSurveyFrequencyMhz);
    ++heard;
  }
  EXPECT_NEAR(tx_sum / heard, kTxDbm, 2.0);

  // After fits the survey better than before, and the blocks it writes load into the scene.
  const auto rb = residuals_per_ap(links, before), ra = residuals_per_ap(links, fit.model);
  EXPECT_LT(ra.back().rms_db, rb.back().rms_db);
  EXPECT_NEAR(ra.back().bias_db, 0.0, 0.1);
  Calibration c;
  c.scene_name = scene.name;
  c.survey_path = survey_path_.string();
  c.frequency_mhz = test::kSurveyFrequencyMhz;
  c.train = links;
  c.before = before;
  c.fit = fit;
  c.baseline = fit_log_distance(links);
  c.shadowing = s;
  std::string yaml;
  std::istringstream lines(test::read_file(scene_path_));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("radio:", 0) == 0 || line.rfind("access_points:", 0) == 0) continue;
    yaml += line + "\n";
  }
  if (::testing::Test::HasFailure()) std::cerr << calibration_report_markdown(c);
  const sim::scene::Scene fitted =
      sim::scene::load_scene_yaml(yaml + calibration_scene_yaml(c), "fitted c_hall");
  ASSERT_TRUE(fitted.radio.distance_coefficient.has_value());
  EXPECT_NEAR(*fitted.radio.distance_coefficient, fit.model.distance_coefficient, 0.01);
  const auto& brick_db =
      fitted.radio.wall_loss_db.by_material_db[static_cast<int>(radio_model::WallMaterial::kBrick)];
  ASSERT_TRUE(brick_db.has_value());
  EXPECT_NEAR(*brick_db, brick.loss_db, 0.01);
  EXPECT_EQ(fitted.access_points.explicit_list.size(), aps.size());
  // The fitted loss reaches the radio model: flat in frequency.
  const auto options = sim::site::propagation_options(fitted);
  EXPECT_NEAR(options.wall_losses.loss_db(radio_model::WallMaterial::kBrick, 5200.0), *brick_db,
              1e-9);
}

}  // namespace
}  // namespace wifislam::radio_model::calibrate
