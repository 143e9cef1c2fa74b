// `wifislam radio calibrate`: fit the itu_walls model's constants (N, wall losses by material,
// shadowing sigma and decorrelation, fast fading, each AP's tx power) to RSS measured at known
// positions, counting walls exactly as the simulator does (radio_model/calibrate/).
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "radio_model/access_point.hpp"
#include "radio_model/calibrate/calibration_report.hpp"
#include "radio_model/calibrate/correlated_intervals.hpp"
#include "radio_model/calibrate/rss_survey.hpp"
#include "radio_model/calibrate/survey_links.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"
#include "sim/site/survey_site.hpp"

namespace wifislam::cli {

namespace {

namespace cal = radio_model::calibrate;

struct CalibrateArgs {
  std::string survey_path, scene_path, aps_path, test_path;
  std::string format = "long";
  double frequency_mhz = 2437.0;  // 2.4 GHz channel 6
  std::optional<double> receiver_height_m;
  std::string output = "fit.yaml";
  std::string report, json;
  std::string reference_device, held_out_device;
  int held_out_positions = 5;
};

std::vector<cal::SurveyAccessPoint> scene_access_points(const sim::site::Site& site) {
  std::vector<cal::SurveyAccessPoint> aps;
  for (const auto& ap : site.access_points())
    aps.push_back({ap.id, ap.position_m, ap.tx_power_dbm, ""});
  return aps;
}

void run_calibrate(const CalibrateArgs& args) {
  // Every output is checked before any work, and written only when everything succeeded.
  std::vector<std::filesystem::path> inputs{args.survey_path, args.scene_path};
  if (!args.aps_path.empty()) inputs.push_back(args.aps_path);
  if (!args.test_path.empty()) inputs.push_back(args.test_path);
  check_output_files({args.output, args.report, args.json}, inputs);

  // A Royal Holloway CSV numbers its access points by column (AP1..AP5, and the corridor's AP1
  // is empty), not by the scene's ids: the positions come with the survey's own ids.
  if (args.format == "royal-holloway" && args.aps_path.empty()) {
    throw InvalidInputError(
        "--format royal-holloway: the survey numbers its access points by column (APk), not by "
        "the scene's ids; give their positions with --aps (for the shipped rooms, "
        "assets/surveys/royal_holloway/<room>_aps.csv)");
  }
  const sim::scene::Scene scene = sim::scene::load_scene_file(args.scene_path);
  if (scene.radio.model != radio_model::PathLossModel::kItuWalls) {
    scene.reject("radio.model",
                 fmt::format("radio calibrate fits the itu_walls model; this scene uses {} (its N "
                             "and sigma come from the ITU tables)",
                             to_string(scene.radio.model)));
  }
  sim::scene::require_height_under_ceiling(scene, args.receiver_height_m, "--receiver-height");
  const sim::site::Site site(scene);
  const double height_m = args.receiver_height_m.value_or(site.receiver_height_m());
  const auto format = args.format == "royal-holloway" ? cal::SurveyFormat::kRoyalHolloway
                                                      : cal::SurveyFormat::kLong;
  const std::vector<cal::SurveyAccessPoint> aps = args.aps_path.empty()
                                                      ? scene_access_points(site)
                                                      : cal::read_access_points_csv(args.aps_path);

  cal::Calibration c;
  c.scene_name = scene.name;
  c.scene_path = args.scene_path;
  c.survey_path = args.survey_path;
  c.test_path = args.test_path;
  c.frequency_mhz = args.frequency_mhz;
  const cal::SurveySite survey_site = sim::site::survey_site(site);
  cal::Survey survey = cal::read_survey(args.survey_path, format, height_m);
  // A held-out device is left out of the fit and scored after it.
  cal::Survey held = survey;
  if (!args.held_out_device.empty()) {
    const std::vector<std::string> devices = survey.devices();
    if (std::find(devices.begin(), devices.end(), args.held_out_device) == devices.end())
      throw InvalidInputError(fmt::format("--held-out-device: {} has no device '{}' (devices: {})",
                                          args.survey_path, args.held_out_device,
                                          fmt::join(devices, ", ")));
    if (args.held_out_device == args.reference_device)
      throw InvalidInputError(fmt::format(
          "--held-out-device: '{}' is the reference device (--reference-device); it cannot be "
          "held out",
          args.held_out_device));
    std::erase_if(survey.samples,
                  [&](const cal::SurveySample& s) { return s.device == args.held_out_device; });
    std::erase_if(held.samples,
                  [&](const cal::SurveySample& s) { return s.device != args.held_out_device; });
    if (survey.samples.empty())
      throw InvalidInputError(
          fmt::format("--held-out-device: {} has no other device to fit", args.survey_path));
  }
  c.train = cal::survey_links(survey, aps, survey_site,
                              cal::devices_reference_first(survey, args.reference_device));
  if (!args.test_path.empty())
    c.test = cal::survey_links(cal::read_survey(args.test_path, format, height_m), aps, survey_site,
                               c.train.devices);
  const radio_model::PropagationOptions& options = survey_site.options;
  c.before = cal::scene_model(c.train, options.wall_losses, scene.radio.distance_coefficient,
                              scene.access_points.tx_power_dbm, args.frequency_mhz);
  c.fit = cal::fit_propagation(c.train, c.before.wall_loss_db);
  c.baseline = cal::fit_log_distance(c.train);
  c.shadowing = cal::shadowing_statistics(c.train, c.fit.model, c.fit.parameters);
  cal::widen_for_correlated_shadowing(c.fit, c.train, c.shadowing);
  if (!args.held_out_device.empty())
    c.held_out = cal::score_held_out_device(
        cal::survey_links(held, aps, survey_site, {args.held_out_device}), c.fit.model, c.baseline,
        args.held_out_positions);

  const std::string markdown = cal::calibration_report_markdown(c);
  const std::string scene_blocks = cal::calibration_scene_yaml(c);
  const std::string json = args.json.empty() ? std::string() : cal::calibration_report_json(c);
  // All or nothing: a report that cannot be written must not leave the fit behind.
  std::vector<std::pair<std::filesystem::path, std::string_view>> files = {
      {args.output, scene_blocks}};
  if (!args.report.empty()) files.emplace_back(args.report, markdown);
  if (!args.json.empty()) files.emplace_back(args.json, json);
  write_files_atomic(files);
  fmt::print("{}wrote {}\n", markdown, args.output);
}

void add_calibrate_command(CLI::App* parent) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* app = parent->add_subcommand(
      "calibrate",
      "Fit N, per-material wall losses, shadowing sigma and decorrelation, fast fading and each\n"
      "AP's tx power to an RSS survey by least squares, counting walls as the simulator does.\n"
      "Writes radio: and access_points: scene blocks (-o) and prints residuals per AP before and\n"
      "after. Survey CSV: x_m,y_m[,z_m],ap_id,rss_dbm[,device] (one row per AP heard per scan;\n"
      "columns in any order; device names the receiver: one RSS offset is fitted per device).");
  app->add_option("survey", args->survey_path, "Survey CSV")->required()->check(kNonEmptyInput);
  app->add_option("--scene", args->scene_path, "Scene file (YAML) of the surveyed building")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("--aps", args->aps_path,
                  "Access points CSV id,x_m,y_m,z_m[,tx_power_dbm]; default: the scene's "
                  "(required with --format royal-holloway, whose ids are its columns)")
      ->check(kNonEmptyInput);
  app->add_option("--format", args->format,
                  "Survey format: long (ours) or royal-holloway (the dataset's CSV as shipped: "
                  "0.6 m grid indices, column APk = AP id k, -200 = not heard)")
      ->capture_default_str()
      ->check(CLI::IsMember({"long", "royal-holloway"}));
  app->add_option("--test", args->test_path,
                  "Held-out survey (same format and APs): residuals reported, not fitted")
      ->check(kNonEmptyInput);
  app->add_option("--frequency-mhz", args->frequency_mhz,
                  "Frequency of the survey: sets the default wall losses compared with and the "
                  "conversion of intercepts to tx power")
      ->capture_default_str()
      ->check(finite_range(2400.0, 7125.0));
  app->add_option("--receiver-height", args->receiver_height_m,
                  "Receiver height (m) for rows without z_m; default: the scene's camera height")
      ->check(kPositiveFinite);
  app->add_option("-o,--output", args->output, "Scene blocks to write (YAML)")
      ->capture_default_str();
  app->add_option("--reference-device", args->reference_device,
                  "Survey with a device column: the device whose offset is 0 (default: the first\n"
                  "in the survey). Every other device gets an RSS offset against it, with its\n"
                  "95 % interval");
  app->add_option("--held-out-device", args->held_out_device,
                  "Leave this device out of the fit and score it on its own samples, without\n"
                  "and with an offset fitted from its first --held-out-positions positions");
  app->add_option("--held-out-positions", args->held_out_positions,
                  "Positions of the held-out device its offset is fitted from (scored on the rest)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app->add_option("--report", args->report, "Also write the report (markdown)")
      ->check(kNonEmptyPath);
  app->add_option("--json", args->json, "Also write the report as JSON")->check(kNonEmptyPath);
  app->callback([args] { run_calibrate(*args); });
}

}  // namespace

WIFISLAM_COMMAND(radio, 45) {
  CLI::App* app = parent.add_subcommand(
      "radio", "Radio model tools: calibrate its constants to a measured RSS survey.");
  app->require_subcommand(1);
  add_calibrate_command(app);
}

}  // namespace wifislam::cli
