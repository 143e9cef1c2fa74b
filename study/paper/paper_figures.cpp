#include "study/paper/paper_figures.hpp"

#include <cmath>
#include <map>
#include <string>

#include <fmt/format.h>

#include "plot/line_chart.hpp"
#include "study/paper/paper_folder.hpp"
#include "study/paper/paper_plan.hpp"

namespace wifislam::study::paper {

namespace {

namespace fs = std::filesystem;

const plot::Colour kVanilla{0.80, 0.25, 0.20}, kWifi{0.15, 0.40, 0.75},
    kPaperVanilla{0.95, 0.6, 0.5}, kPaperWifi{0.55, 0.7, 0.95};

std::string axis_label(Quantity q) {
  switch (q) {
    case Quantity::kAteRmseM:
      return "ATE RMSE (m)";
    case Quantity::kFalseNegativePct:
      return "false negatives (% of revisits missed)";
    case Quantity::kFalsePositivePct:
      return "false positives (% of loop closures)";
    case Quantity::kWifiOverheadS:
      return "Wi-Fi overhead (s)";
    default:
      return to_string(q);
  }
}

plot::ChartPoint point(double x, const Measured& m) { return {x, m.mean(), m.min(), m.max()}; }

/// Draws `chart` as figures/<stem>.png and .svg.
PaperFigure draw(const fs::path& folder, Part part, const std::string& stem,
                 const plot::LineChart& chart, const std::string& caption) {
  const fs::path dir = folder / folder::kFigures;
  fs::create_directories(dir);
  plot::draw_line_chart(dir / (stem + ".png"), chart);
  plot::draw_line_chart(dir / (stem + ".svg"), chart);
  return {part, std::string(folder::kFigures) + "/" + stem + ".png", caption};
}

/// Copies a run's picture (PNG and SVG) into figures/<stem>; nothing when it is missing.
std::optional<PaperFigure> copy_picture(const fs::path& folder, Part part, const fs::path& source,
                                        const std::string& stem, const std::string& caption) {
  if (!fs::exists(source.string() + ".png")) return std::nullopt;
  const fs::path dir = folder / folder::kFigures;
  fs::create_directories(dir);
  for (const char* ext : {".png", ".svg"}) {
    if (fs::exists(source.string() + ext)) {
      fs::copy_file(source.string() + ext, dir / (stem + ext),
                    fs::copy_options::overwrite_existing);
    }
  }
  return PaperFigure{part, std::string(folder::kFigures) + "/" + stem + ".png", caption};
}

void rgbdslam_figures(const PaperMeasurements& m, const fs::path& folder,
                      std::vector<PaperFigure>& out) {
  const std::vector<int> mms = {50, 70, 100, 150};
  const std::vector<int> ids = {2, 3, 4};
  if (m.settings(Part::kRgbdslam, "c_hall").empty()) return;
  struct Panel {
    const char* stem;
    const char* column;
    const char* y_label;
    const char* what;
  };
  for (const Panel& panel :
       {Panel{"rgbdslam_sweep_false_positives", "false_positive_pct",
              "wrong-place loop closures (% of scored)", "False positive loop closures"},
        Panel{"rgbdslam_sweep_time", "paper_loop_closure_s", "bounded-module time (s)",
              "Computation time (bounded module)"},
        Panel{"rgbdslam_sweep_error", "ate_rmse_m", "ATE RMSE (m)", "Trajectory error"}}) {
    plot::LineChart chart;
    chart.title = std::string(panel.what) + " against min-matches and inlier distance (C Hall)";
    chart.subtitle = "vanilla solid, Wi-Fi dashed; band: min-max over seeds";
    chart.x_label = "min-matches";
    chart.y_label = panel.y_label;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (bool wifi : {false, true}) {
        plot::ChartSeries s;
        s.label = fmt::format("inlier distance {} px{}", ids[i], wifi ? ", Wi-Fi" : "");
        s.colour = plot::category_colour(static_cast<std::int64_t>(i));
        s.dashed = wifi;
        for (int mm : mms) {
          const Measured v = m.column(Part::kRgbdslam, "c_hall",
                                      fmt::format("min_matches={} inlier_distance={}", mm, ids[i]),
                                      wifi, panel.column);
          if (!v.empty()) s.points.push_back(point(mm, v));
        }
        if (!s.points.empty()) chart.series.push_back(std::move(s));
      }
    }
    out.push_back(draw(folder, Part::kRgbdslam, panel.stem, chart,
                       std::string(panel.what) + " as min-matches and inlier distance vary (the "
                                                 "paper's 3 x 4 figure), vanilla and Wi-Fi"));
  }
  const fs::path runs = folder / folder::kRuns;
  const std::string seed = std::to_string(twin_scene("c_hall").seed);
  for (int mm : {100, 150}) {
    if (auto f = copy_picture(
            folder, Part::kRgbdslam,
            runs / ("rgbdslam-c_hall-seed" + seed) /
                fmt::format("min_matches-{}_inlier_distance-2", mm) / "vanilla" / "eval" /
                "trajectory",
            fmt::format("rgbdslam_bad_map_min_matches_{}", mm),
            fmt::format("Vanilla RGBD-SLAM's map with min-matches {} and inlier distance 2 (the "
                        "paper's bad maps), seed {}",
                        mm, seed))) {
      out.push_back(*f);
    }
  }
  for (int mm : {50, 70}) {
    for (bool wifi : {false, true}) {
      if (auto f = copy_picture(
              folder, Part::kRgbdslam,
              runs / ("rgbdslam-c_hall-seed" + seed) /
                  fmt::format("min_matches-{}_inlier_distance-3", mm) /
                  (wifi ? "wifi" : "vanilla") / "eval" / "trajectory",
              fmt::format("rgbdslam_map_min_matches_{}_{}", mm, wifi ? "wifi" : "vanilla"),
              fmt::format("{} RGBD-SLAM at min-matches {} (C Hall, seed {})",
                          wifi ? "Wi-Fi" : "Vanilla", mm, seed))) {
        out.push_back(*f);
      }
    }
  }
}

/// One chart per building of a paper table: ours (vanilla, Wi-Fi; seeds' range as a band) and
/// the paper's (dashed, lighter), against the table's settings. Times: the Wi-Fi / vanilla ratio.
void table_figures(const PaperTable& table, const std::vector<ComparedNumber>& compared,
                   const PaperMeasurements& m, const fs::path& folder,
                   std::vector<PaperFigure>& out) {
  const bool ratio = table.quantity == Quantity::kLoopClosureTimeS;
  for (const std::string& row : table.rows) {
    const std::string hall = row.substr(0, row.find('&') - 1);
    std::string twin;
    for (const std::string& t : twin_names())
      if (hall_name(t) == hall) twin = t;
    std::map<Variant, plot::ChartSeries> ours, paper;
    plot::LineChart chart;
    chart.title = fmt::format("{}: {}", hall, table.caption.substr(0, table.caption.find(" for ")));
    chart.subtitle = ratio ? "Wi-Fi / vanilla loop-closure time; ours solid (band: seeds' range), "
                             "the paper's dashed"
                           : "ours solid (band: seeds' range), the paper's dashed";
    chart.x_label = table.setting_key;
    chart.y_label = ratio ? "Wi-Fi / vanilla loop-closure time" : axis_label(table.quantity);
    chart.x_categories = table.settings;
    bool any = false;
    for (std::size_t s = 0; s < table.settings.size(); ++s) {
      const std::string setting = table.setting_key + "=" + table.settings[s];
      if (ratio) {
        const auto [v, w] = m.paired(table.part, twin, setting, "paper_loop_closure_s");
        Measured r;
        for (std::size_t i = 0; i < v.per_seed.size(); ++i)
          if (v.per_seed[i] > 0) r.per_seed.push_back(w.per_seed[i] / v.per_seed[i]);
        double pv = 0, pw = 0;
        for (const ComparedNumber& c : compared) {
          const PaperNumber& n = *c.paper;
          if (n.source != table.label || n.twin != twin || n.setting != setting) continue;
          (n.variant == Variant::kVanilla ? pv : pw) = n.value;
        }
        auto& o = ours[Variant::kWifi];
        auto& p = paper[Variant::kWifi];
        if (!r.empty()) {
          o.points.push_back(point(static_cast<double>(s), r));
          any = true;
        }
        if (pv > 0) p.points.push_back({static_cast<double>(s), pw / pv, pw / pv, pw / pv});
        continue;
      }
      for (const ComparedNumber& c : compared) {
        const PaperNumber& n = *c.paper;
        if (n.source != table.label || n.twin != twin || n.setting != setting) continue;
        const double x = static_cast<double>(s);
        paper[n.variant].points.push_back({x, n.value, n.value, n.value});
        if (!c.ours.empty() && n.quantity != Quantity::kWifiOverheadS) {
          ours[n.variant].points.push_back(point(x, c.ours));
          any = true;
        }
      }
    }
    if (!any) continue;
    for (auto& [variant, s] : ours) {
      s.label =
          ratio ? "ours" : fmt::format("ours, {}", variant == Variant::kWifi ? "Wi-Fi" : "vanilla");
      s.colour = variant == Variant::kWifi ? kWifi : kVanilla;
      chart.series.push_back(s);
    }
    for (auto& [variant, s] : paper) {
      s.label = ratio
                    ? "the paper"
                    : fmt::format("the paper, {}", variant == Variant::kWifi ? "Wi-Fi" : "vanilla");
      s.colour = variant == Variant::kWifi ? kPaperWifi : kPaperVanilla;
      s.dashed = true;
      chart.series.push_back(s);
    }
    const std::string stem = table.label.substr(6) + "_" + twin;
    out.push_back(draw(folder, table.part, stem, chart,
                       fmt::format("{}, {}: ours beside the paper's", table.caption, hall)));
  }
}

void rtabmap_maps(const fs::path& folder, std::vector<PaperFigure>& out) {
  for (const char* twin : {"j_hall", "a_hall"}) {
    const std::string seed = std::to_string(twin_scene(twin).seed);
    for (bool wifi : {false, true}) {
      if (auto f = copy_picture(
              folder, Part::kRtabmap,
              folder / folder::kRuns / fmt::format("rtabmap-{}-seed{}", twin, seed) /
                  "time_threshold_ms-70" / (wifi ? "wifi" : "vanilla") / "eval" / "trajectory",
              fmt::format("rtabmap_map_{}_70ms_{}", twin, wifi ? "wifi" : "vanilla"),
              fmt::format("{} RTAB-Map on {} at a real-time threshold of 70 ms "
                          "(seed {}; the paper's figure shows J Hall)",
                          wifi ? "Wi-Fi" : "Vanilla", hall_name(twin), seed))) {
        out.push_back(*f);
      }
    }
  }
}

void fabmap_figures(const PaperMeasurements& m, const fs::path& folder,
                    std::vector<PaperFigure>& out) {
  for (const std::string& twin : twin_names()) {
    const auto it = m.localisations().find(twin);
    if (it == m.localisations().end() || it->second.empty()) continue;
    const std::uint64_t seed = it->second.begin()->first;
    if (auto f = copy_picture(folder, Part::kFabmap,
                              folder / folder::kLocalize / folder::twin_seed(twin, seed) / "cdf",
                              "fabmap_cdf_" + twin,
                              fmt::format("Localisation error CDF on {} (seed {}): visual FAB-MAP, "
                                          "Wi-Fi FAB-MAP and ours",
                                          hall_name(twin), seed))) {
      out.push_back(*f);
    }
  }
}

}  // namespace

std::vector<PaperFigure> draw_paper_figures(const PaperMeasurements& measurements,
                                            const std::vector<ComparedNumber>& compared,
                                            const fs::path& folder) {
  std::vector<PaperFigure> out;
  rgbdslam_figures(measurements, folder, out);
  for (const PaperTable& table : paper_tables()) {
    table_figures(table, compared, measurements, folder, out);
    if (table.label == "table:rtabmap_overhead") rtabmap_maps(folder, out);
  }
  fabmap_figures(measurements, folder, out);
  return out;
}

}  // namespace wifislam::study::paper
