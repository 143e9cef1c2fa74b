#include "study/localisation_report.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/median.hpp"
#include "plot/line_chart.hpp"

namespace wifislam::study {

namespace {

constexpr double kShareLimitsM[] = {1.0, 2.0, 4.0, 5.0};

std::vector<const QueryResult*> of_method(const LocalisationResult& r, LocalisationMethod m) {
  std::vector<const QueryResult*> out;
  for (const QueryResult& q : r.queries) {
    if (q.method == m) out.push_back(&q);
  }
  return out;
}

double share_within(const std::vector<const QueryResult*>& queries, double limit_m,
                    bool with_map_nearby) {
  int n = 0, within = 0;
  for (const QueryResult* q : queries) {
    if (with_map_nearby && q->nearest_map_m > kTrueMatchM) continue;
    ++n;
    within += q->within(limit_m);
  }
  return n > 0 ? static_cast<double>(within) / n : 0.0;
}

std::string queries_csv(const LocalisationResult& r, const LocalisationData& data) {
  // With another floor in the map, a last column says whether the chosen image is on it (the
  // file of a one-floor run keeps its columns).
  const bool floors = r.other_floor_images > 0;
  std::string out =
      "method,query_time,query_x_m,query_y_m,chosen_time,chosen_x_m,chosen_y_m,probability,"
      "error_m,nearest_map_m,candidates,time_s";
  out += floors ? ",wrong_floor\n" : "\n";
  for (const QueryResult& q : r.queries) {
    const LocalisationImage& a = data.images[static_cast<std::size_t>(q.query)];
    const LocalisationImage& b = data.images[static_cast<std::size_t>(q.chosen)];
    out += fmt::format("{},{},{:.3f},{:.3f},{},{:.3f},{:.3f},{:.6g},{:.3f},{:.3f},{},{:.6f}",
                       to_string(q.method), a.time.to_tum_string(), a.position_m.x(),
                       a.position_m.y(), b.time.to_tum_string(), b.position_m.x(), b.position_m.y(),
                       q.probability, q.error_m, q.nearest_map_m, q.candidates, q.time_s);
    out += floors ? fmt::format(",{}\n", q.wrong_floor ? 1 : 0) : "\n";
  }
  return out;
}

/// Per method, its errors sorted: the CDF's steps.
std::string cdf_csv(const LocalisationResult& r, const LocalisationOptions& o,
                    plot::LineChart& chart) {
  std::string out = "method,error_m,share\n";
  int colour = 0;
  for (LocalisationMethod m : o.methods) {
    // A query matched on another floor has no error on its own: it counts in the shares'
    // denominator and never in a step, so the curve ends below 1.
    std::vector<double> errors;
    const std::vector<const QueryResult*> queries = of_method(r, m);
    for (const QueryResult* q : queries)
      if (!q->wrong_floor) errors.push_back(q->error_m);
    std::sort(errors.begin(), errors.end());
    plot::ChartSeries series{to_string(m), plot::category_colour(colour++), false, {}};
    series.points.push_back({0.0, 0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < errors.size(); ++i) {
      const double share = static_cast<double>(i + 1) / static_cast<double>(queries.size());
      out += fmt::format("{},{:.3f},{:.6f}\n", to_string(m), errors[i], share);
      series.points.push_back({errors[i], share, share, share});
    }
    chart.series.push_back(std::move(series));
  }
  return out;
}

/// Precision and recall as the match-probability threshold falls through each query's value.
std::string pr_csv(const LocalisationResult& r, const LocalisationOptions& o,
                   plot::LineChart& chart) {
  std::string out = "method,threshold,precision,recall\n";
  int colour = 0;
  for (LocalisationMethod m : o.methods) {
    plot::ChartSeries series{to_string(m), plot::category_colour(colour++), false, {}};
    std::vector<const QueryResult*> queries = of_method(r, m);
    std::stable_sort(
        queries.begin(), queries.end(),
        [](const QueryResult* a, const QueryResult* b) { return a->probability > b->probability; });
    int positives = 0;
    for (const QueryResult* q : queries) positives += q->nearest_map_m <= kTrueMatchM;
    // One point per distinct threshold: queries of equal probability are accepted together.
    int accepted = 0, correct = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      ++accepted;
      correct += queries[i]->within(kTrueMatchM);
      if (i + 1 < queries.size() && queries[i + 1]->probability == queries[i]->probability)
        continue;
      const double precision = static_cast<double>(correct) / accepted;
      const double recall = positives > 0 ? static_cast<double>(correct) / positives : 0.0;
      out += fmt::format("{},{:.6g},{:.4f},{:.4f}\n", to_string(m), queries[i]->probability,
                         precision, recall);
      series.points.push_back({recall, precision, precision, precision});  // recall never falls
    }
    chart.series.push_back(std::move(series));
  }
  return out;
}

std::string summary_markdown(const nlohmann::ordered_json& s) {
  std::string out = fmt::format("# Localisation: {}\n\n{} map images, {} queries.\n\n",
                                s["input"].get<std::string>(), s["map_images"].get<int>(),
                                s["query_images"].get<int>());
  if (s.contains("queries_from_another_run"))
    out += "The map is the whole input; the queries are another run of its route.\n\n";
  const bool floors = s.contains("other_floor_images");
  if (floors) {
    out += fmt::format(
        "{} of the map images are of another floor; a query that chooses one is on the wrong "
        "floor, within no distance.\n\n",
        s["other_floor_images"].get<int>());
  }
  out +=
      "| method | within 1 m | 2 m | 4 m | 5 m | (queries with a map image within 2 m:) 1 m | "
      "2 m | 4 m | 5 m | median time per query (ms) |";
  out += floors ? " wrong floor |\n| --- |" : "\n| --- |";
  for (int column = 0; column < (floors ? 10 : 9); ++column) out += " ---: |";
  out += "\n";
  for (const auto& m : s["methods"]) {
    out += "| " + m["method"].get<std::string>() + " |";
    for (const char* set : {"all", "map_within_2m"}) {
      for (const auto& v : m[set]) out += fmt::format(" {:.1f} % |", 100.0 * v.get<double>());
    }
    out += fmt::format(" {:.2f} |", 1e3 * m["median_time_s"].get<double>());
    if (floors) out += fmt::format(" {:.1f} % |", 100.0 * m["wrong_floor"].get<double>());
    out += "\n";
  }
  return out;
}

}  // namespace

nlohmann::ordered_json localisation_summary(const LocalisationResult& result,
                                            const LocalisationOptions& options) {
  nlohmann::ordered_json methods = nlohmann::ordered_json::array();
  for (LocalisationMethod m : options.methods) {
    const std::vector<const QueryResult*> queries = of_method(result, m);
    nlohmann::ordered_json all = nlohmann::ordered_json::object(), near = all;
    std::vector<double> times;
    for (const QueryResult* q : queries) times.push_back(q->time_s);
    for (double limit : kShareLimitsM) {
      const std::string key = fmt::format("within_{:g}m", limit);
      all[key] = share_within(queries, limit, false);
      near[key] = share_within(queries, limit, true);
    }
    methods.push_back({{"method", to_string(m)},
                       {"queries", queries.size()},
                       {"all", all},
                       {"map_within_2m", near},
                       {"median_time_s", median(times)}});
    if (result.other_floor_images > 0) {
      const auto wrong = std::count_if(queries.begin(), queries.end(),
                                       [](const QueryResult* q) { return q->wrong_floor; });
      methods.back()["wrong_floor"] =
          queries.empty() ? 0.0 : static_cast<double>(wrong) / static_cast<double>(queries.size());
    }
  }
  nlohmann::ordered_json summary = {{"input", result.description},
                                    {"map_images", result.map_images},
                                    {"query_images", result.query_images}};
  // One run split in time, or the queries of another run (add_query_session).
  if (result.queries_from_another_run)
    summary["queries_from_another_run"] = true;
  else
    summary["map_share"] = options.map_share;
  summary["methods"] = methods;
  if (result.other_floor_images > 0) summary["other_floor_images"] = result.other_floor_images;
  return summary;
}

void write_localisation_report(const std::filesystem::path& dir, const LocalisationResult& result,
                               const LocalisationData& data, const LocalisationOptions& options) {
  write_file_atomic(dir / "queries.csv", queries_csv(result, data));
  plot::LineChart chart;
  chart.title = "Localisation error: share of queries within an error";
  chart.subtitle = result.description;
  chart.x_label = "error (m)";
  chart.y_label = "share of queries";
  write_file_atomic(dir / "cdf.csv", cdf_csv(result, options, chart));
  plot::draw_line_chart(dir / "cdf.png", chart);
  plot::draw_line_chart(dir / "cdf.svg", chart);
  plot::LineChart pr;
  pr.title = "Precision-recall of the match probability (a match is true within 2 m)";
  pr.subtitle = result.description;
  pr.x_label = "recall (of the queries with a map image within 2 m)";
  pr.y_label = "precision";
  write_file_atomic(dir / "pr.csv", pr_csv(result, options, pr));
  plot::draw_line_chart(dir / "pr.png", pr);
  plot::draw_line_chart(dir / "pr.svg", pr);
  const nlohmann::ordered_json summary = localisation_summary(result, options);
  write_file_atomic(dir / "summary.json", summary.dump(1) + "\n");
  write_file_atomic(dir / "summary.md", summary_markdown(summary));
}

}  // namespace wifislam::study
