#include "study/study_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "plot/line_chart.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

struct MetricSpec {
  const char* column;
  const char* label;  // y axis
  const char* note;   // which way is better
};

// The metrics drawn per level, in figure order.
const std::vector<MetricSpec>& radio_metrics() {
  static const std::vector<MetricSpec> m = {
      {"resolution_m", "signature resolution [m]",
       "beyond it pause pairs stay below wifi_similarity; lower is better"},
      {"far_similar_share", "share of pause pairs > 12 m apart counted similar",
       "lower is better: far look-alikes the Wi-Fi would let through"},
      {"near_similar_share", "share of pause pairs < 4 m apart counted similar",
       "higher is better: the same place recognised"},
      {"aps_heard_per_pause", "access points heard per pause", ""},
      {"clusters", "Wi-Fi clusters along the route", ""}};
  return m;
}

const std::vector<MetricSpec>& slam_metrics() {
  static const std::vector<MetricSpec> m = {
      {"far_wrong_place_closures", "wrong-place loop closures between places > 12 m apart",
       "accepted online; the paper's false loop closures between far look-alikes"},
      {"wrong_place_closures", "wrong-place loop closures", "accepted online"},
      {"false_positive_pct", "false positive loop closures [%]", "wrong place, accepted online"},
      {"ate_rmse_m", "ATE RMSE [m]", "aligned SE(3), lower is better"},
      {"false_negative_pct", "false negatives [% of revisit episodes]", "lower is better"},
      {"far_wrong_place_after_pruning", "far wrong-place closures after pruning",
       "what the back end kept"},
      {"long_term_comparisons", "long-term candidate comparisons", "the work bounding saves"}};
  return m;
}

bool is_seed_axis(const std::string& key) {
  return key == "seed" || (key.size() > 5 && key.compare(key.size() - 5, 5, ".seed") == 0);
}

std::string value_text(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return "NULL";
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) return fmt::format("{:g}", *d);
  return std::get<std::string>(v);
}

std::optional<double> number(const SqlValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  return std::nullopt;
}

struct AxisColumn {
  std::string key;
  int column = -1;
  std::vector<SqlValue> values;  // distinct, in first-seen order (study order)
  bool numeric = true;
};

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

StudyPlotSummary plot_study(const ResultTable& table, const fs::path& folder) {
  const bool slam = table.identity.level == "slam";
  const std::vector<MetricSpec>& metrics = slam ? slam_metrics() : radio_metrics();
  const int variant_col = table.column("variant");
  if (variant_col < 0) throw InvalidInputError("study database: the results table has no variant");

  // The axes and their distinct values.
  std::vector<AxisColumn> axes;
  for (const std::string& key : table.identity.axis_keys) {
    AxisColumn a;
    a.key = key;
    a.column = table.column(column_name(key));
    if (a.column < 0) throw InvalidInputError("study database: no column for axis " + key);
    for (const auto& row : table.rows) {
      const SqlValue& v = row[static_cast<std::size_t>(a.column)];
      if (std::find(a.values.begin(), a.values.end(), v) == a.values.end()) a.values.push_back(v);
      a.numeric = a.numeric && number(v).has_value();
    }
    axes.push_back(std::move(a));
  }

  // x: a preferred axis, else the first numeric one that varies, else the first that varies.
  int x_axis = -1;
  for (const char* preferred : {"access_points.count", "appearance.aliasing"}) {
    for (std::size_t i = 0; i < axes.size() && x_axis < 0; ++i)
      if (axes[i].key == preferred && axes[i].values.size() > 1) x_axis = static_cast<int>(i);
  }
  for (std::size_t i = 0; i < axes.size() && x_axis < 0; ++i)
    if (axes[i].numeric && axes[i].values.size() > 1 && !is_seed_axis(axes[i].key))
      x_axis = static_cast<int>(i);
  for (std::size_t i = 0; i < axes.size() && x_axis < 0; ++i)
    if (axes[i].values.size() > 1 && !is_seed_axis(axes[i].key)) x_axis = static_cast<int>(i);

  StudyPlotSummary summary;
  std::vector<int> line_axes;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (static_cast<int>(i) == x_axis || axes[i].values.size() < 2) continue;
    if (is_seed_axis(axes[i].key)) {
      summary.pooled_axes.push_back(axes[i].key);
    } else {
      line_axes.push_back(static_cast<int>(i));
      summary.line_axes.push_back(axes[i].key);
    }
  }
  summary.x_axis = x_axis >= 0 ? axes[static_cast<std::size_t>(x_axis)].key : "";
  const bool categorical_x = x_axis < 0 || !axes[static_cast<std::size_t>(x_axis)].numeric;
  std::vector<std::string> categories;
  if (categorical_x) {
    if (x_axis >= 0) {
      for (const SqlValue& v : axes[static_cast<std::size_t>(x_axis)].values)
        categories.push_back(value_text(v));
    } else {
      categories.push_back("all cases");
    }
  }
  const auto x_of = [&](const std::vector<SqlValue>& row) {
    if (x_axis < 0) return 0.0;
    const AxisColumn& a = axes[static_cast<std::size_t>(x_axis)];
    const SqlValue& v = row[static_cast<std::size_t>(a.column)];
    if (!categorical_x) return *number(v);
    return static_cast<double>(std::find(a.values.begin(), a.values.end(), v) - a.values.begin());
  };
  // A line: the values of the line axes (in study order of their values) and the variant.
  using LineKey = std::pair<std::vector<std::size_t>, std::string>;
  const auto line_of = [&](const std::vector<SqlValue>& row) {
    LineKey key;
    for (int a : line_axes) {
      const AxisColumn& axis = axes[static_cast<std::size_t>(a)];
      const SqlValue& v = row[static_cast<std::size_t>(axis.column)];
      key.first.push_back(static_cast<std::size_t>(
          std::find(axis.values.begin(), axis.values.end(), v) - axis.values.begin()));
    }
    key.second = value_text(row[static_cast<std::size_t>(variant_col)]);
    return key;
  };
  const auto line_label = [&](const LineKey& key) {
    std::string label;
    for (std::size_t i = 0; i < line_axes.size(); ++i) {
      const AxisColumn& axis = axes[static_cast<std::size_t>(line_axes[i])];
      const std::string short_key = axis.key.substr(axis.key.rfind('.') + 1);
      label += (i ? ", " : "") + short_key + " " + value_text(axis.values[key.first[i]]);
    }
    if (slam) label += (label.empty() ? "" : ", ") + key.second;
    return label.empty() ? std::string("all cases") : label;
  };

  std::string csv = "metric,line,x,cases,median,min,max\n";
  const std::string pooled =
      summary.pooled_axes.empty()
          ? std::string("one case per point")
          : fmt::format("median over {}, band from the smallest to the largest",
                        fmt::join(summary.pooled_axes, ", "));
  for (const MetricSpec& metric : metrics) {
    const int col = table.column(metric.column);
    if (col < 0) continue;
    // line -> x -> values (+inf for NULL: no resolution)
    std::map<LineKey, std::map<double, std::vector<double>>> points;
    for (const auto& row : table.rows) {
      const auto v = number(row[static_cast<std::size_t>(col)]);
      points[line_of(row)][x_of(row)].push_back(v ? *v : std::numeric_limits<double>::infinity());
    }
    plot::LineChart chart;
    chart.title = fmt::format("{}: {}", table.identity.name, metric.label);
    chart.subtitle = fmt::format("{}{}{}", pooled, *metric.note ? "; " : "", metric.note);
    chart.x_label = x_axis >= 0 ? axes[static_cast<std::size_t>(x_axis)].key : "";
    chart.y_label = metric.label;
    chart.x_categories = categories;
    // Colours by the line axes' values, Wi-Fi solid and vanilla dashed in one colour; with no
    // line axis, a colour per variant as well.
    std::map<LineKey, std::int64_t> colour_index;
    for (const auto& [key, by_x] : points) {
      const LineKey colour_key{key.first, line_axes.empty() ? key.second : std::string()};
      const auto [it, added] =
          colour_index.emplace(colour_key, static_cast<std::int64_t>(colour_index.size()));
      plot::ChartSeries series;
      series.label = line_label(key);
      series.colour = plot::category_colour(it->second);
      series.dashed = key.second == "vanilla";
      for (const auto& [x, values_in] : by_x) {
        std::vector<double> values = values_in;
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (double v : values)
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        plot::ChartPoint p;
        p.x = x;
        p.y = std::isfinite(median) ? median : std::numeric_limits<double>::quiet_NaN();
        p.y_lo = std::isfinite(median) ? lo : p.y;
        p.y_hi = std::isfinite(median) ? hi : p.y;
        series.points.push_back(p);
        const std::string x_text =
            categorical_x ? categories[static_cast<std::size_t>(x)] : fmt::format("{:g}", x);
        const auto cell = [](double v) { return std::isfinite(v) ? fmt::format("{:g}", v) : ""; };
        csv += fmt::format("{},{},{},{},{},{},{}\n", metric.column, csv_field(series.label),
                           csv_field(x_text), n, cell(median), cell(lo), cell(hi));
      }
      chart.series.push_back(std::move(series));
    }
    for (const char* extension : {".png", ".svg"}) {
      const fs::path figure = folder / (std::string(metric.column) + extension);
      plot::draw_line_chart(figure, chart);
      summary.figures.push_back(figure);
    }
  }
  write_file_atomic(folder / "curves.csv", csv);
  return summary;
}

}  // namespace wifislam::study
