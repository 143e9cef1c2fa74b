// Working Memory over time for rtabmap runs (issue "RTAB-Map-style front end", benchmark "WM size
// over time"): reads rtabmap_memory.csv of run folders and draws, per node, the WM size of each
// run (vanilla dashed, Wi-Fi solid), with the nodes Wi-Fi immunisation kept in WM (immune) as a
// second line under each Wi-Fi run; a point every ~1/120 of the run. Also prints, per run, the
// largest and mean WM, the LTM size at the end, transfers and retrievals.
//
//   rtabmap_memory_plot -o FIGURE.png [--title TEXT] LABEL:RUN_DIR ...
//
// The variant is the run's run.json "wifi", never guessed from the folder's name.

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/run_format.hpp"
#include "core/text_lines.hpp"
#include "plot/line_chart.hpp"
#include "slam/frontend/rtabmap/rtabmap_memory_csv.hpp"

namespace {

namespace fs = std::filesystem;
using namespace wifislam;

struct MemoryRun {
  std::string label;
  bool wifi = false;
  std::vector<double> wm, ltm, immune;  // per node, after its memory management
  long long transferred = 0, retrieved = 0;
};

MemoryRun read_run(const std::string& label, const fs::path& folder) {
  MemoryRun run;
  run.label = label;
  const fs::path run_json = folder / run_folder::kRun;
  std::ifstream in(run_json);
  if (!in) throw IoError(run_json.string() + ": cannot be read (not a run folder?)");
  nlohmann::json meta;
  try {
    in >> meta;
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(run_json.string(), "", std::string("not valid JSON: ") + e.what());
  }
  if (meta.value(run_folder::run_key::kFrontend, std::string()) != "rtabmap") {
    throw InvalidInputError(folder.string() + " is not an rtabmap run (run.json frontend)");
  }
  run.wifi = meta.value(run_folder::run_key::kWifi, false);

  namespace col = slam::frontend::rtabmap::rtabmap_memory_csv::column;
  const auto index_of = [](const char* name) {
    return static_cast<std::size_t>(
        std::find_if(col::kAll.begin(), col::kAll.end(),
                     [&](const char* c) { return std::string_view(c) == name; }) -
        col::kAll.begin());
  };
  const std::size_t wm = index_of("wm"), ltm = index_of("ltm"), immune = index_of("immune"),
                    transferred = index_of("transferred"), retrieved = index_of("retrieved"),
                    wifi_retrieved = index_of("wifi_retrieved");
  for_each_csv_row((folder / slam::frontend::rtabmap::rtabmap_memory_csv::kFileName).string(),
                   col::kAll, [&](const CsvRow& row) {
                     const auto number = [&](std::size_t column) {
                       long long v = 0;
                       if (!parse_int64(row.fields[column], v)) {
                         throw ParseError(
                             row.where, col::kAll[column],
                             "'" + std::string(row.fields[column]) + "' is not a whole number");
                       }
                       return v;
                     };
                     run.wm.push_back(static_cast<double>(number(wm)));
                     run.ltm.push_back(static_cast<double>(number(ltm)));
                     run.immune.push_back(static_cast<double>(number(immune)));
                     run.transferred += number(transferred);
                     run.retrieved += number(retrieved) + number(wifi_retrieved);
                   });
  return run;
}

int usage() {
  fmt::print(stderr, "usage: rtabmap_memory_plot -o FIGURE.png [--title TEXT] LABEL:RUN_DIR ...\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path figure;
  std::string title = "rtabmap: Working Memory size per node";
  std::vector<std::pair<std::string, fs::path>> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" || arg == "--output" || arg == "--title") {
      if (++i >= argc) return usage();
      if (arg == "--title") {
        title = argv[i];
      } else {
        figure = argv[i];
      }
      continue;
    }
    const std::size_t colon = arg.find(':');
    if (colon == std::string::npos || colon == 0) {
      fmt::print(stderr, "'{}' is not LABEL:RUN_DIR\n", arg);
      return usage();
    }
    inputs.emplace_back(arg.substr(0, colon), fs::path(arg.substr(colon + 1)));
  }
  if (figure.empty() || inputs.empty()) return usage();
  try {
    plot::LineChart chart;
    chart.title = title;
    chart.subtitle = "vanilla dashed, Wi-Fi solid; \"(immune)\": WM nodes Wi-Fi immunisation kept";
    chart.x_label = "node";
    chart.y_label = "nodes";
    const plot::Colour palette[] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16}, {0.17, 0.63, 0.17},
                                    {0.58, 0.40, 0.74}, {1.00, 0.50, 0.05}, {0.55, 0.34, 0.29}};
    fmt::print(
        "| run | variant | nodes | largest WM | mean WM | LTM at the end | transfers | "
        "retrievals |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    std::size_t k = 0;
    for (const auto& [label, folder] : inputs) {
      const MemoryRun run = read_run(label, folder);
      const plot::Colour colour = palette[k++ % std::size(palette)];
      plot::ChartSeries wm{run.label, colour, !run.wifi, {}};
      plot::ChartSeries immune{run.label + " (immune)", colour, false, {}};
      double sum = 0;
      // About 120 points a line: the chart marks every point, and dashes need room between marks.
      const std::size_t step = std::max<std::size_t>(1, run.wm.size() / 120);
      for (std::size_t n = 0; n < run.wm.size(); ++n) {
        sum += run.wm[n];
        if (n % step != 0 && n + 1 != run.wm.size()) continue;
        const double x = static_cast<double>(n);
        wm.points.push_back({x, run.wm[n], run.wm[n], run.wm[n]});
        immune.points.push_back({x, run.immune[n], run.immune[n], run.immune[n]});
      }
      chart.series.push_back(std::move(wm));
      if (run.wifi) chart.series.push_back(std::move(immune));
      fmt::print("| {} | {} | {} | {:.0f} | {:.1f} | {:.0f} | {} | {} |\n", run.label,
                 run.wifi ? "Wi-Fi" : "vanilla", run.wm.size(),
                 run.wm.empty() ? 0.0 : *std::max_element(run.wm.begin(), run.wm.end()),
                 run.wm.empty() ? 0.0 : sum / static_cast<double>(run.wm.size()),
                 run.ltm.empty() ? 0.0 : run.ltm.back(), run.transferred, run.retrieved);
    }
    plot::draw_line_chart(figure, chart);
    fmt::print("wrote {}\n", figure.string());
  } catch (const std::exception& e) {
    fmt::print(stderr, "rtabmap_memory_plot: {}\n", e.what());
    return 1;
  }
  return 0;
}
