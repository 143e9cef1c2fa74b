// Scaling of the orbslam front end's loop-detection query (bench/slam/orbslam_scaling.sh): reads
// orbslam run folders of ladders of 1, 2, 4, 8 ... wings, vanilla and Wi-Fi, and writes
//   scaling.csv  one row per run: wings, variant, keyframes in the map, loop-detection queries
//                (keyframes with detection_ran = 1), mean / median / 90th percentile of the
//                keyframes searched and postings read per query, median query_ms, mean indexes
//                read per query, for Wi-Fi runs the clusters and their mean size (keyframes per
//                cluster, wifi_clusters.csv), and keyframes made after a tracking loss (run.json)
//   keyframes_searched_vs_{wings,map}.{png,svg}, postings_read_vs_{wings,map}.{png,svg}
//                the median per query against wings and against keyframes in the map, one line
//                per variant (vanilla dashed, Wi-Fi solid), band from the 10th to the 90th
//                percentile of the queries; the keyframes-searched figures also draw the Wi-Fi
//                runs' mean cluster size.
//
//   orbslam_scaling_plot -o OUT_DIR WINGS:RUN_DIR ...
//
// The variant is the run's run.json "wifi", never guessed from the folder's name.

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/run_format.hpp"
#include "core/text_lines.hpp"
#include "eval/wifi_clusters_csv.hpp"
#include "plot/line_chart.hpp"
#include "slam/frontend/orbslam/orbslam_queries_csv.hpp"

namespace {

namespace fs = std::filesystem;
using namespace wifislam;

struct RunSummary {
  int wings = 0;
  bool wifi = false;
  fs::path folder;
  long long map_keyframes = 0;
  long long keyframes_after_tracking_loss = 0;
  // Per query that ran (detection_ran = 1), in keyframe order.
  std::vector<double> databases_searched, keyframes_searched, postings_read, query_ms;
  long long clusters = 0;
  double mean_cluster_size = std::numeric_limits<double>::quiet_NaN();
};

/// Linear interpolation between order statistics (q in [0, 1]); NaN for no values.
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double pos = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

std::string cell(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string(); }

const char* variant_name(bool wifi) { return wifi ? "wifi" : "vanilla"; }

RunSummary read_run(int wings, const fs::path& folder) {
  RunSummary run;
  run.wings = wings;
  run.folder = folder;
  const fs::path run_json = folder / run_folder::kRun;
  std::ifstream in(run_json);
  if (!in) throw IoError("cannot read " + run_json.string());
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInputError(run_json.string() + ": " + e.what());
  }
  if (meta.value(run_folder::run_key::kFrontend, std::string()) != "orbslam") {
    throw InvalidInputError(folder.string() + " is not an orbslam run (run.json frontend)");
  }
  if (!meta.contains(run_folder::run_key::kWifi) || !meta.contains("keyframes")) {
    throw InvalidInputError(run_json.string() + " has no \"wifi\" or \"keyframes\"");
  }
  run.wifi = meta.at(run_folder::run_key::kWifi).get<bool>();
  run.map_keyframes = meta.at("keyframes").get<long long>();
  run.keyframes_after_tracking_loss = meta.value("keyframes_after_tracking_loss", 0LL);

  namespace col = slam::frontend::orbslam::orbslam_queries_csv::column;
  const auto index_of = [](const char* name) {
    return static_cast<std::size_t>(
        std::find_if(col::kAll.begin(), col::kAll.end(),
                     [&](const char* c) { return std::string_view(c) == name; }) -
        col::kAll.begin());
  };
  const std::size_t ran = index_of("detection_ran");
  const std::pair<std::size_t, std::vector<double>*> wanted[] = {
      {index_of("databases_searched"), &run.databases_searched},
      {index_of("keyframes_searched"), &run.keyframes_searched},
      {index_of("postings_read"), &run.postings_read},
      {index_of("query_ms"), &run.query_ms}};
  long long rows = 0;
  for_each_csv_row((folder / slam::frontend::orbslam::orbslam_queries_csv::kFileName).string(),
                   col::kAll, [&](const CsvRow& row) {
                     ++rows;
                     if (row.fields[ran] != "1") return;
                     for (const auto& [column, values] : wanted) {
                       double v = 0;
                       if (!parse_double(row.fields[column], v)) {
                         throw ParseError(
                             row.where, col::kAll[column],
                             "'" + std::string(row.fields[column]) + "' is not a number");
                       }
                       values->push_back(v);
                     }
                   });
  if (rows != run.map_keyframes) {
    throw InvalidInputError(
        fmt::format("{}: {} rows in {} but {} keyframes in run.json", folder.string(), rows,
                    slam::frontend::orbslam::orbslam_queries_csv::kFileName, run.map_keyframes));
  }
  if (run.wifi) {
    const std::vector<eval::WifiCluster> clusters =
        eval::read_wifi_clusters_csv(folder / run_folder::kWifiClusters);
    run.clusters = static_cast<long long>(clusters.size());
    if (!clusters.empty()) {
      double members = 0;
      for (const eval::WifiCluster& c : clusters)
        members += static_cast<double>(c.keyframes.size());
      run.mean_cluster_size = members / static_cast<double>(clusters.size());
    }
  }
  return run;
}

std::string scaling_csv(const std::vector<RunSummary>& runs) {
  std::string csv =
      "wings,variant,map_keyframes,queries,mean_keyframes_searched,median_keyframes_searched,"
      "p90_keyframes_searched,mean_postings_read,median_postings_read,p90_postings_read,"
      "median_query_ms,mean_databases_searched,wifi_clusters,mean_cluster_size,"
      "keyframes_after_tracking_loss,run\n";
  for (const RunSummary& r : runs) {
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.wings,
                       variant_name(r.wifi), r.map_keyframes, r.keyframes_searched.size(),
                       cell(mean(r.keyframes_searched)), cell(quantile(r.keyframes_searched, 0.5)),
                       cell(quantile(r.keyframes_searched, 0.9)), cell(mean(r.postings_read)),
                       cell(quantile(r.postings_read, 0.5)), cell(quantile(r.postings_read, 0.9)),
                       cell(quantile(r.query_ms, 0.5)), cell(mean(r.databases_searched)),
                       r.wifi ? std::to_string(r.clusters) : "", cell(r.mean_cluster_size),
                       r.keyframes_after_tracking_loss, r.folder.string());
  }
  return csv;
}

/// One figure: the median of `metric` per query against wings or map keyframes.
void draw(const std::vector<RunSummary>& runs, bool x_is_map, bool postings,
          const fs::path& out_dir) {
  plot::LineChart chart;
  const std::string what = postings ? "inverted-index postings read per loop-detection query"
                                    : "keyframes searched per loop-detection query";
  chart.title = fmt::format("orbslam: {}", what);
  chart.subtitle = fmt::format(
      "ladders of identical wings (aliasing 1.0); median over the queries, band 10th-90th "
      "percentile{}",
      postings ? "" : "; grey: Wi-Fi runs' mean cluster size");
  chart.x_label = x_is_map ? "keyframes in the map (end of run)" : "wings";
  chart.y_label = postings ? "postings read per query" : "keyframes searched per query";
  const auto x_of = [&](const RunSummary& r) {
    return x_is_map ? static_cast<double>(r.map_keyframes) : static_cast<double>(r.wings);
  };
  for (bool wifi : {false, true}) {
    plot::ChartSeries series;
    series.label = wifi ? "Wi-Fi" : "vanilla";
    series.colour = plot::category_colour(wifi ? 1 : 0);
    series.dashed = !wifi;
    for (const RunSummary& r : runs) {
      if (r.wifi != wifi) continue;
      const std::vector<double>& v = postings ? r.postings_read : r.keyframes_searched;
      plot::ChartPoint p;
      p.x = x_of(r);
      p.y = quantile(v, 0.5);
      p.y_lo = std::isfinite(p.y) ? quantile(v, 0.1) : p.y;
      p.y_hi = std::isfinite(p.y) ? quantile(v, 0.9) : p.y;
      series.points.push_back(p);
    }
    std::sort(series.points.begin(), series.points.end(),
              [](const plot::ChartPoint& a, const plot::ChartPoint& b) { return a.x < b.x; });
    if (!series.points.empty()) chart.series.push_back(std::move(series));
  }
  if (!postings) {
    plot::ChartSeries clusters;
    clusters.label = "Wi-Fi mean cluster size";
    clusters.colour = {0.55, 0.55, 0.55};
    for (const RunSummary& r : runs) {
      if (!r.wifi) continue;
      plot::ChartPoint p;
      p.x = x_of(r);
      p.y = p.y_lo = p.y_hi = r.mean_cluster_size;
      clusters.points.push_back(p);
    }
    std::sort(clusters.points.begin(), clusters.points.end(),
              [](const plot::ChartPoint& a, const plot::ChartPoint& b) { return a.x < b.x; });
    if (!clusters.points.empty()) chart.series.push_back(std::move(clusters));
  }
  const std::string stem = fmt::format(
      "{}_vs_{}", postings ? "postings_read" : "keyframes_searched", x_is_map ? "map" : "wings");
  for (const char* extension : {".png", ".svg"}) {
    plot::draw_line_chart(out_dir / (stem + extension), chart);
  }
}

int usage() {
  fmt::print(stderr, "usage: orbslam_scaling_plot -o OUT_DIR WINGS:RUN_DIR ...\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path out_dir;
  std::vector<std::pair<int, fs::path>> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" || arg == "--output") {
      if (++i >= argc) return usage();
      out_dir = argv[i];
      continue;
    }
    const std::size_t colon = arg.find(':');
    long long wings = 0;
    if (colon == std::string::npos || !parse_int64(std::string_view(arg).substr(0, colon), wings) ||
        wings < 1) {
      fmt::print(stderr, "'{}' is not WINGS:RUN_DIR\n", arg);
      return usage();
    }
    inputs.emplace_back(static_cast<int>(wings), fs::path(arg.substr(colon + 1)));
  }
  if (out_dir.empty() || inputs.empty()) return usage();
  try {
    std::vector<RunSummary> runs;
    for (const auto& [wings, folder] : inputs) runs.push_back(read_run(wings, folder));
    std::sort(runs.begin(), runs.end(), [](const RunSummary& a, const RunSummary& b) {
      return a.wings != b.wings ? a.wings < b.wings : a.wifi < b.wifi;
    });
    fs::create_directories(out_dir);
    write_file_atomic(out_dir / "scaling.csv", scaling_csv(runs));
    for (bool x_is_map : {false, true}) {
      for (bool postings : {false, true}) draw(runs, x_is_map, postings, out_dir);
    }
    fmt::print("wrote {}/scaling.csv and the figures\n", out_dir.string());
  } catch (const std::exception& e) {
    fmt::print(stderr, "orbslam_scaling_plot: {}\n", e.what());
    return 1;
  }
  return 0;
}
